#!/usr/bin/env bash
# The slab mode against MCML 1.2.2 side by side on MCML's own three-layer sample (its manual's
# sample.mci: n 1.37, layers mua/mus/g/d = 1/100/0.9/0.1, 1/10/0/0.1, 2/10/0.7/0.2 cm), one thread.
#   bench/mcml-side-by-side.sh MCML_SOURCE [BUILD]
# MCML_SOURCE: the MCML 1.2.2 folder holding src/mcml/*.c (e.g. 1.2.2/ of github.com/mhjlam/MCML);
# it is compiled here with gcc -O3, with one change: the seed of its ran3 is read from MCML_SEED
# instead of the clock (time(NULL)), so that many runs can be started at once with distinct seeds.
#
# Time: K runs of N photons each, user CPU seconds per whole process (median), for MCML, hylios
# slab (the default: the weighted walk in eight single-precision lanes), `--scalar` (the same laws
# one packet at a time in double precision) and `--scheme analog`.
# Variance per photon of Rd, Tt and A: hylios' from its own per-packet standard errors over the
# K·N photons (N · stderr², averaged over the runs); MCML's from the spread of M runs of n photons
# (seeds 1..M): n · variance across the runs, uncertain by a factor sqrt(2/(M − 1)) (±14 % at 100).
# Efficiency = 1 / (time per photon x variance per photon), relative to MCML.
# Environment: K (default 5), N (1000000), M (100), n (100000).
set -euo pipefail
mcml_source="$(cd "${1:?usage: bench/mcml-side-by-side.sh MCML_SOURCE [BUILD]}" && pwd)"
shift
source "$(dirname "$0")/common.sh"
build="$(cd "$build" && pwd)"
K=${K:-5}
N=${N:-1000000}
M=${M:-100}
n=${n:-100000}
mkdir "$work/mcml-src"
cp "$mcml_source"/src/mcml/*.c "$mcml_source"/src/mcml/*.h "$work/mcml-src/"
sed -i 's|idum = -(int)time(NULL)%(1<<15);|idum = -(getenv("MCML_SEED") ? atoi(getenv("MCML_SEED")) : (int)time(NULL))%(1<<15);|' \
  "$work/mcml-src/mcmlgo.c"
grep -q MCML_SEED "$work/mcml-src/mcmlgo.c" || { echo "MCML's seed line was not found" >&2; exit 1; }
gcc -O3 -o "$work/mcml" "$work"/mcml-src/*.c -lm
mci() {  # mci PHOTONS > file
  printf '1.0\n1\nout.mco A\n%s\n0.01 0.01\n40 50 1\n3\n1.0\n1.37 1 100 0.90 0.1\n1.37 1 10 0 0.1\n1.37 2 10 0.70 0.2\n1.0\n' "$1"
}
layers=(--layer n=1.37,mua=1,mus=100,g=0.9,d=0.1 --layer n=1.37,mua=1,mus=10,g=0,d=0.1
        --layer n=1.37,mua=2,mus=10,g=0.7,d=0.2)
# The RAT block of an .mco: specular, diffuse reflectance, absorbed fraction, transmittance.
rat() { awk '/^RAT/{f=1;next} f&&NF>=1&&c<4{v[c++]=$1} END{print v[1]","v[3]","v[2]}' "$1"; }
cd "$work"
mci "$N" > timing.mci
mci "$n" > spread.mci
echo "tool,run,user_s,Rd,Tt,A,Rd_se,Tt_se,A_se" > timing.csv
for i in $(seq 1 "$K"); do
  MCML_SEED=$i /usr/bin/time -f "%U" -o t.txt ./mcml timing.mci > /dev/null
  echo "mcml,$i,$(cat t.txt),$(rat out.mco),,," >> timing.csv
  for variant in lanes scalar analog; do
    case $variant in
      lanes) extra=() ;;
      scalar) extra=(--scalar) ;;
      analog) extra=(--scheme analog) ;;
    esac
    /usr/bin/time -f "%U" -o t.txt "$build/hylios" slab "${layers[@]}" --rays "$N" --threads 1 \
      --seed "$i" "${extra[@]}" --out h.csv > /dev/null
    echo "hylios-$variant,$i,$(cat t.txt),$(tail -1 h.csv | awk -F, '{print $2","$4","$7","$3","$5","$8}')" >> timing.csv
  done
done
echo "Rd,Tt,A" > spread.csv
for i in $(seq 1 "$M"); do
  mkdir -p "s$i"
  (cd "s$i" && MCML_SEED=$i ../mcml ../spread.mci > /dev/null && rat out.mco >> ../spread.csv) &
  if (( i % $(nproc) == 0 )); then wait; fi
done
wait
echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), K=$K runs of N=$N photons; MCML spread: M=$M runs of n=$n"
N=$N n=$n python3 - <<'PY'
import csv, os, statistics as st
N, n = int(os.environ['N']), int(os.environ['n'])
rows = list(csv.DictReader(open('timing.csv')))
spread = list(csv.DictReader(open('spread.csv')))
quantities = ['Rd', 'Tt', 'A']
base = {}
print("| tool | median CPU s per run | Rd | Tt | A | sd per photon Rd / Tt / A | efficiency Rd / Tt / A (× MCML) |")
print("|---|---|---|---|---|---|---|")
for tool in ['mcml', 'hylios-lanes', 'hylios-scalar', 'hylios-analog']:
    r = [x for x in rows if x['tool'] == tool]
    t = st.median(float(x['user_s']) for x in r) / N
    means, sds, eff = [], [], []
    for q in quantities:
        means.append(f"{st.mean(float(x[q]) for x in r):.5f}")
        if tool == 'mcml':
            var = n * st.variance(float(x[q]) for x in spread)
        else:
            var = N * st.mean(float(x[q + '_se']) ** 2 for x in r)
        sds.append(f"{var ** 0.5:.4f}")
        e = 1 / (t * var)
        base.setdefault(q, e)
        eff.append(f"{e / base[q]:.2f}")
    print(f"| {tool} | {t * N:.2f} | " + " | ".join(means) + " | " + " / ".join(sds) + " | " + " / ".join(eff) + " |")
PY
