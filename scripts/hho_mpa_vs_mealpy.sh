#!/usr/bin/env bash
# tidepath's HHO and MPA on Rastrigin-30 (60,000 evaluations, population 40, range [-5.12,
# 5.12]) beside MEALPY 3.0.3's HHO.OriginalHHO and MPA.OriginalMPA on about the same budget,
# back to back on this machine, several times over; prints each side's median seconds per run,
# median best cost, and the speed ratios.
#
#   scripts/hho_mpa_vs_mealpy.sh [RUNS]        (default 5)
#
# Installs MEALPY into a virtual environment under target/ (PyPI must be reachable) and
# builds tidepath in release mode. tidepath's time per run is the optimizer's own (runs.csv's
# elapsed_s: no process start-up); MEALPY's is model.solve's. Both run on one core. MEALPY's
# epoch counts are chosen so its evaluation counts come out near 60,000 (the reckoning is in
# scripts/mealpy/hho_mpa_rastrigin.py; each run prints its own count). The algorithms differ in
# places (docs/papers/shared.md, HHO and MPA): the ratios compare speed, not results.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
venv=target/mealpy-venv
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q "mealpy==3.0.3"
fi
cargo build --release -q -p tidepath-cli
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
column() { head -1 "$1" | tr ',' '\n' | grep -n "^$2\$" | cut -d: -f1; }

for algo in hho mpa; do
  target/release/tidepath bench functions --algos "$algo" --funcs rastrigin --range small --dim 30 \
    --population 40 --evaluations 60000 --runs "$runs" --jobs 1 --out "$out/$algo" >/dev/null
  csv="$out/$algo/runs.csv"
  tail -n +2 "$csv" | cut -d, -f"$(column "$csv" elapsed_s)" | median > "$out/$algo.time"
  tail -n +2 "$csv" | cut -d, -f"$(column "$csv" cost)" | median > "$out/$algo.cost"
  tail -n +2 "$csv" | cut -d, -f"$(column "$csv" evaluations)" | sort -u | tr '\n' ' ' > "$out/$algo.evals"
done
OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 "$venv/bin/python" scripts/mealpy/hho_mpa_rastrigin.py "$runs" > "$out/mealpy.txt"
for algo in hho mpa; do
  grep "^$algo " "$out/mealpy.txt" | cut -d' ' -f2 | median > "$out/mealpy-$algo.time"
  grep "^$algo " "$out/mealpy.txt" | cut -d' ' -f3 | median > "$out/mealpy-$algo.cost"
  grep "^$algo " "$out/mealpy.txt" | cut -d' ' -f4 | tr '\n' ' ' > "$out/mealpy-$algo.evals"
done

echo "Rastrigin-30, range [-5.12, 5.12], population 40, $runs runs each: median seconds per run, median best cost"
for algo in hho mpa; do
  name=$(echo "$algo" | tr a-z A-Z)
  echo "  MEALPY 3.0.3 Original$name  $(cat "$out/mealpy-$algo.time") s  best $(cat "$out/mealpy-$algo.cost")  (evaluations: $(cat "$out/mealpy-$algo.evals"))"
  echo "  tidepath $algo               $(cat "$out/$algo.time") s  best $(cat "$out/$algo.cost")  (evaluations: $(cat "$out/$algo.evals"))"
done
awk -v mh="$(cat "$out/mealpy-hho.time")" -v th="$(cat "$out/hho.time")" \
    -v mm="$(cat "$out/mealpy-mpa.time")" -v tm="$(cat "$out/mpa.time")" \
    'BEGIN { printf "  MEALPY / tidepath: HHO %.0fx, MPA %.0fx\n", mh / th, mm / tm }'
