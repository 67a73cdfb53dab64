# Sourced by the bench scripts (after `set -euo pipefail`; `source "$(dirname "$0")/common.sh"`)
# for what they share:
#   root   the source tree            build  the build folder: the script's $1, else $root/build
#   work   a temporary folder, removed when the script exits
#   HYLIOS_DATA_DIR exported as $root
#   lambertian SCENE RHO   SCENE with its skin material replaced by a diffuse one of reflectance RHO
#   figure01_variant NAME RHO VARIANT   sets `file` and `extra` (render arguments) for the Figure 1
#                          band NAME with the skin's VARIANT estimator (spectral, per-wavelength) or,
#                          for VARIANT lambertian, a diffuse stand-in of reflectance RHO
#   worst  the largest percentage in `hylios image-diff --noise` output on stdin (the worst group)
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export HYLIOS_DATA_DIR="$root"

lambertian() {
  sed -e 's/^type = "skin"/type = "diffuse"\nreflectance = '"$2"'/' -e '/^specimen = /d' -e '/^freckles = /d' \
    -e 's|"\.\./assets/|"'"$root"'/assets/|' "$1"
}

figure01_variant() {
  file="$root/scenes/figure01_$1.toml"
  extra=(--estimator "$3")
  if [ "$3" = lambertian ]; then
    lambertian "$file" "$2" > "$work/lambertian_$1.toml"
    file="$work/lambertian_$1.toml"
    extra=()
  fi
}

worst() { sed -n 's/^[^:]*: \([0-9.]*\) %.*/\1/p' | sort -g | tail -1; }
