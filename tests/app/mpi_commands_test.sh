#!/usr/bin/env bash
# Commands under MPI and the sweep's journal, run as processes (registered by tests/CMakeLists.txt;
# the mpi_* cases only in a build with MPI). Usage: mpi_commands_test.sh HYLIOS CASE.
#   mpi_spectrum      spectrum at -np 2 and -np 3: the CSV byte-identical to one process
#   mpi_profiles      brdf (both estimators) and radial-profile at -np 2/3: CSVs byte-identical;
#                     a command that does not divide its work is refused under -np 2
#   mpi_render        render at -np 2 (also with a noise target): the EXR byte-identical to one
#                     process but for its DateTime attribute (the time of writing), PNG identical
#   mpi_sweep_resume  sweep at -np 2 killed after 3 journaled cases (rank 0 ends as by SIGKILL),
#                     then resumed at -np 2: byte-identical to an uninterrupted one-process sweep
#   mpi_rank_dies     a worker rank ends abruptly: the job fails (non-zero) within the timeout, no
#                     output file, the journal kept; --resume then completes it
#   sweep_killed      no MPI: a sweep ended abruptly after 2 cases, resumed, equals an
#                     uninterrupted sweep; a --resume of another sweep's journal is refused
set -euo pipefail
hylios=$1
case_name=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/hylios-mpi-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
# --bind-to none: Open MPI binds each rank to one core by default (np <= 2), which would pin a
# rank and its threads to a core other processes of a shared machine also use.
# HYLIOS_MPIRUN: the launcher CMake found (tests/CMakeLists.txt), else mpirun from PATH.
mpirun=("${HYLIOS_MPIRUN:-mpirun}" --allow-run-as-root --oversubscribe --bind-to none)
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
same() { cmp "$1" "$2" || fail "$1 and $2 differ"; }
# An EXR with its DateTime value ("YYYY:MM:DD HH:MM:SS", written by OpenImageIO) blanked.
timeless() {
  python3 -c 'import re,sys; d=open(sys.argv[1],"rb").read(); sys.stdout.buffer.write(re.sub(rb"\d{4}:\d\d:\d\d \d\d:\d\d:\d\d", b"-"*19, d))' "$1"
}
sweep_args=(sweep --specimen S2 --vary melanosome=1:7:2 --vary blood=0.2:1:0.4 --wavelengths
  450,600 --angle 0,45 --rays 3000 --seed 7)

case $case_name in
  mpi_spectrum)
    args=(spectrum --specimen S1 --angle 45 --wavelengths 400:700:30 --rays 20000 --seed 3)
    "$hylios" "${args[@]}" --threads 2 --out one.csv
    "${mpirun[@]}" -np 2 "$hylios" "${args[@]}" --threads 1 --out two.csv
    "${mpirun[@]}" -np 3 "$hylios" "${args[@]}" --threads 1 --out three.csv
    [ "$(wc -l <one.csv)" -eq 12 ] || fail "one.csv: expected a header and 11 rows"
    same one.csv two.csv
    same one.csv three.csv
    ;;
  mpi_profiles)
    # Tallies with histograms (brdf: directions; radial-profile: exit radii), both estimators.
    brdf=(brdf --specimen S1 --angle 30 --wavelengths 450,550,650 --rays 6000 --seed 5)
    "$hylios" "${brdf[@]}" --threads 2 --out brdf1.csv
    "${mpirun[@]}" -np 2 "$hylios" "${brdf[@]}" --threads 1 --out brdf2.csv
    same brdf1.csv brdf2.csv
    "$hylios" "${brdf[@]}" --estimator per-wavelength --out brdfw1.csv
    "${mpirun[@]}" -np 2 "$hylios" "${brdf[@]}" --estimator per-wavelength --threads 1 \
      --out brdfw2.csv
    same brdfw1.csv brdfw2.csv
    radial=(radial-profile --specimen S2 --wavelength 550 --rays 8000 --bins 20 --seed 2)
    "$hylios" "${radial[@]}" --out radial1.csv
    "${mpirun[@]}" -np 3 "$hylios" "${radial[@]}" --threads 1 --out radial3.csv
    same radial1.csv radial3.csv
    # A command that does not divide its work refuses to run on several ranks, with one message.
    if "${mpirun[@]}" -np 2 "$hylios" coefficients --specimen S1 --wavelengths 550 \
      --out c.csv 2>err.txt; then
      fail "coefficients ran under mpirun -np 2"
    fi
    [ "$(grep -c 'does not divide its work among MPI ranks' err.txt)" -eq 1 ] ||
      fail "expected one refusal: $(cat err.txt)"
    ;;
  mpi_render)
    scene=$HYLIOS_DATA_DIR/scenes/test/skin_sphere_550.toml
    "$hylios" render "$scene" --resolution 40x36 --spp 6 --seed 11 --threads 2 --out one.exr
    "${mpirun[@]}" -np 2 "$hylios" render "$scene" --resolution 40x36 --spp 6 --seed 11 \
      --threads 1 --out two.exr
    same <(timeless one.exr) <(timeless two.exr)
    same one_nm550.png two_nm550.png
    # A noise target: rank 0 decides when to stop from the summed film, every rank stops there.
    # (The walk, not the scene's exit tables: 287 of them would be built for these 576 pixels.)
    visible=$HYLIOS_DATA_DIR/scenes/figure01_visible.toml
    "$hylios" render "$visible" --resolution 24x24 --spp 64 --noise-target 0.3 --skin-model walk \
      --out n1.exr
    "${mpirun[@]}" -np 2 "$hylios" render "$visible" --resolution 24x24 --spp 64 \
      --noise-target 0.3 --skin-model walk --threads 1 --out n2.exr
    same <(timeless n1.exr) <(timeless n2.exr)
    # A bad --out fails on every rank with rank 0's one message, before any work.
    if "${mpirun[@]}" -np 2 "$hylios" render "$scene" --out missing/x.exr 2>err.txt; then
      fail "render into a missing folder succeeded"
    fi
    [ "$(grep -c 'hylios: error' err.txt)" -eq 1 ] || fail "expected one error line: $(cat err.txt)"
    ;;
  mpi_sweep_resume)
    "$hylios" "${sweep_args[@]}" --out whole.csv
    if HYLIOS_TEST_SWEEP_EXIT=0:3 "${mpirun[@]}" -np 2 "$hylios" "${sweep_args[@]}" --threads 1 \
      --out part.csv 2>/dev/null; then
      fail "the killed sweep exited 0"
    fi
    [ ! -e part.csv ] || fail "a killed sweep left part.csv"
    [ "$(grep -c '^end ' part.csv.partial)" -ge 3 ] || fail "the journal lacks 3 cases"
    "${mpirun[@]}" -np 2 "$hylios" "${sweep_args[@]}" --threads 1 --out part.csv --resume
    same whole.csv part.csv
    [ ! -e part.csv.partial ] || fail "the journal was not removed"
    ;;
  mpi_rank_dies)
    start=$(date +%s)
    status=0
    HYLIOS_TEST_SWEEP_EXIT=1:1 timeout 120 "${mpirun[@]}" -np 2 "$hylios" "${sweep_args[@]}" \
      --threads 1 --out dead.csv 2>err.txt || status=$?
    [ "$status" -ne 0 ] || fail "the job whose rank 1 died exited 0"
    [ "$status" -ne 124 ] || fail "the job hung (killed by the timeout)"
    [ ! -e dead.csv ] || fail "a failed job left dead.csv"
    [ -e dead.csv.partial ] || fail "the journal is gone"
    echo "job failed with status $status after $(($(date +%s) - start)) s"
    "$hylios" "${sweep_args[@]}" --out whole.csv
    "${mpirun[@]}" -np 2 "$hylios" "${sweep_args[@]}" --threads 1 --out dead.csv --resume
    same whole.csv dead.csv
    ;;
  sweep_killed)
    "$hylios" "${sweep_args[@]}" --out whole.csv
    status=0
    HYLIOS_TEST_SWEEP_EXIT=0:2 "$hylios" "${sweep_args[@]}" --out part.csv 2>/dev/null || status=$?
    [ "$status" -eq 137 ] || fail "expected the test exit status 137, got $status"
    [ ! -e part.csv ] || fail "a killed sweep left part.csv"
    [ "$(grep -c '^end ' part.csv.partial)" -eq 2 ] || fail "the journal should hold 2 cases"
    # Another sweep (a third angle) refuses this journal and changes nothing.
    cp part.csv.partial before.partial
    if "$hylios" "${sweep_args[@]}" --angle 30 --out part.csv --resume 2>err.txt; then
      fail "a sweep with another angle list took the journal"
    fi
    grep -q "journal of another sweep" err.txt || fail "unclear message: $(cat err.txt)"
    same before.partial part.csv.partial
    "$hylios" "${sweep_args[@]}" --out part.csv --resume
    same whole.csv part.csv
    ;;
  *)
    fail "unknown case '$case_name'"
    ;;
esac
echo "PASS $case_name"
