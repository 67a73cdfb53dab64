#!/usr/bin/env bash
# Builds the benchmarks (Release), runs bench/skin_walk_bench and bench/full-curve.sh, and writes
# docs/benchmarks.md with the machine description (nproc, CPU model, date, git commit).
# usage: bench/run-benchmarks.sh [BUILD_DIR]   (default build-bench; needs Google Benchmark)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-bench}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHYLIOS_BUILD_BENCHMARKS=ON \
  -DHYLIOS_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target hylios skin_walk_bench -j"$(nproc)" >/dev/null
if [[ ! -x "$build/bench/skin_walk_bench" ]]; then
  echo "Google Benchmark was not found: no bench/skin_walk_bench" >&2
  exit 1
fi
walk=$(HYLIOS_DATA_DIR="$root" "$build/bench/skin_walk_bench" --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true 2>/dev/null | grep -E "_median|^-|^Benchmark")
curve=$("$root/bench/full-curve.sh" "$build")
# The commit checked out, read from .git without running git (HEAD, loose ref or packed-refs).
commit=unknown
if [[ -f "$root/.git/HEAD" ]]; then
  head=$(cat "$root/.git/HEAD")
  if [[ "$head" == ref:* ]]; then
    ref=${head#ref: }
    if [[ -f "$root/.git/$ref" ]]; then commit=$(cat "$root/.git/$ref")
    elif [[ -f "$root/.git/packed-refs" ]]; then commit=$(awk -v r="$ref" '$2 == r {print $1}' "$root/.git/packed-refs"); fi
  else
    commit=$head
  fi
fi
commit="${commit:0:12} (the working tree may hold later changes)"
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //')
{
  echo "# Benchmarks"
  echo
  echo "Written by \`bench/run-benchmarks.sh\`; rerun it to refresh. Figures are CPU-time rates"
  echo "(items_per_second = rays or photons per CPU second, one thread), so they hold on a shared"
  echo "machine; the full-curve wall time depends on how busy the machine was."
  echo
  echo "| machine | |"
  echo "|---|---|"
  echo "| date | $(date -u '+%Y-%m-%d %H:%M UTC') |"
  echo "| git commit | $commit |"
  echo "| nproc | $(nproc) |"
  echo "| CPU | $cpu |"
  echo "| load average at start | $(cut -d' ' -f1-3 /proc/loadavg) |"
  echo
  echo "## HyLIoS walk and MCML slab (\`bench/skin_walk_bench\`, median of 3)"
  echo
  echo "skinWalk/S*/λ: rays per CPU second at 45° incidence, full model; mcmlThreeLayerSlab:"
  echo "photons per CPU second, MCML manual's three-layer sample, analog absorption."
  echo
  echo '```'
  echo "$walk"
  echo '```'
  echo
  echo "## Full S1 curve (\`bench/full-curve.sh\`)"
  echo
  echo '```'
  echo "$curve"
  echo '```'
  if [[ -f "$root/docs/benchmarks-recorded.md" ]]; then
    echo
    sed -e 's/^## /### /' -e 's/^# /## /' "$root/docs/benchmarks-recorded.md"
  fi
} > "$root/docs/benchmarks.md"
cat "$root/docs/benchmarks.md"
