#!/usr/bin/env bash
# The slab mode against MCML 1.2.2 side by side on MCML's own three-layer sample (its manual's
# sample.mci: n 1.37, layers mua/mus/g/d = 1/100/0.9/0.1, 1/10/0/0.1, 2/10/0.7/0.2 cm): K runs of
# N photons each, one thread, user CPU seconds per run; variance of Rd, Tt and A across the runs;
# efficiency 1 / (median time x variance) for MCML, hylios slab --scheme weighted and analog.
#   bench/mcml-side-by-side.sh MCML_SOURCE [BUILD]
# MCML_SOURCE: the MCML 1.2.2 folder holding src/mcml/*.c (e.g. 1.2.2/ of github.com/mhjlam/MCML);
# it is compiled here with gcc -O3. MCML seeds itself from the clock (time(NULL)), so the runs are
# a second apart. Environment: K (runs, default 10), N (photons per run, default 1000000).
set -euo pipefail
mcml_source="$(cd "${1:?usage: bench/mcml-side-by-side.sh MCML_SOURCE [BUILD]}" && pwd)"
shift
source "$(dirname "$0")/common.sh"
build="$(cd "$build" && pwd)"
K=${K:-10}
N=${N:-1000000}
gcc -O3 -o "$work/mcml" "$mcml_source"/src/mcml/*.c -lm
cat > "$work/run.mci" <<MCI
1.0
1
out.mco A
$N
0.01 0.01
40 50 1
3
1.0
1.37 1 100 0.90 0.1
1.37 1 10 0 0.1
1.37 2 10 0.70 0.2
1.0
MCI
layers=(--layer n=1.37,mua=1,mus=100,g=0.9,d=0.1 --layer n=1.37,mua=1,mus=10,g=0,d=0.1
        --layer n=1.37,mua=2,mus=10,g=0.7,d=0.2)
cd "$work"
echo "tool,run,user_s,Rd,Tt,A" > results.csv
for i in $(seq 1 "$K"); do
  /usr/bin/time -f "%U" -o t.txt ./mcml run.mci > /dev/null
  # RAT block of the .mco: specular, diffuse reflectance, absorbed fraction, transmittance
  echo "mcml,$i,$(cat t.txt),$(awk '/^RAT/{f=1;next} f&&NF>=1&&n<4{v[n++]=$1} END{print v[1]","v[3]","v[2]}' out.mco)" >> results.csv
  for scheme in weighted analog; do
    /usr/bin/time -f "%U" -o t.txt "$build/hylios" slab "${layers[@]}" --rays "$N" --threads 1 \
      --seed "$i" --scheme "$scheme" --out h.csv > /dev/null
    echo "hylios-$scheme,$i,$(cat t.txt),$(tail -1 h.csv | awk -F, '{print $2","$4","$7}')" >> results.csv
  done
  sleep 1
done
echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), K=$K runs of N=$N photons"
python3 - <<'PY'
import csv, statistics as st
rows = list(csv.DictReader(open('results.csv')))
base = {}
print("| tool | median CPU s per run | Rd ± sd | Tt ± sd | A ± sd | efficiency Rd / Tt / A (× MCML) |")
print("|---|---|---|---|---|---|")
for tool in ['mcml', 'hylios-weighted', 'hylios-analog']:
    r = [x for x in rows if x['tool'] == tool]
    t = st.median(float(x['user_s']) for x in r)
    cells, eff = [], []
    for q in ['Rd', 'Tt', 'A']:
        v = [float(x[q]) for x in r]
        var = st.variance(v)
        cells.append(f"{st.mean(v):.5f} ± {var ** 0.5:.5f}")
        e = 1 / (t * var)
        base.setdefault(q, e)
        eff.append(f"{e / base[q]:.2f}")
    print(f"| {tool} | {t:.2f} | " + " | ".join(cells) + " | " + " / ".join(eff) + " |")
PY
