#!/usr/bin/env bash
# Formats the tracked C++ sources with clang-format and the project's .clang-format.
#   scripts/format.sh           rewrite the files in place
#   scripts/format.sh --check   change nothing; list the files that need formatting, exit 1 if any
set -euo pipefail
cd "$(dirname "$0")/.."
format=${CLANG_FORMAT:-clang-format}
command -v "$format" >/dev/null || { echo "format.sh: $format not found (apt-get install clang-format)" >&2; exit 2; }
mapfile -t files < <(git ls-files -- '*.cpp' '*.h' '*.hpp')
if [[ ${1:-} == --check ]]; then
  bad=0
  for f in "${files[@]}"; do
    if ! "$format" --style=file "$f" | cmp -s - "$f"; then echo "$f"; bad=1; fi
  done
  if (( bad )); then echo "format.sh: the files above need scripts/format.sh" >&2; fi
  exit "$bad"
elif [[ $# -gt 0 ]]; then
  echo "usage: scripts/format.sh [--check]" >&2; exit 2
fi
printf '%s\0' "${files[@]}" | xargs -0 -n 50 "$format" --style=file -i
