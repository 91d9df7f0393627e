#!/usr/bin/env bash
# One 60,000-evaluation run of tidepath's AMFA on Rastrigin-30 beside one of MEALPY 3's
# FFA.OriginalFFA on the same budget (population 40, amfa2015's small range), back to back on
# this machine, several times over; prints each side's median seconds per run and the ratio.
#
#   scripts/amfa_vs_mealpy.sh [RUNS]        (default 5)
#
# Installs MEALPY into a virtual environment under target/ (PyPI must be reachable) and
# builds tidepath in release mode. tidepath's time per run is the optimizer's own (runs.csv's
# elapsed_s: no process start-up); MEALPY's is model.solve's. Both run on one core.
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

for algo in amfa fa; do
  rm -rf "$out/$algo"
  target/release/tidepath bench functions --algos "$algo" --funcs rastrigin --range small --dim 30 \
    --population 40 --evaluations 60000 --runs "$runs" --jobs 1 --preset amfa2015 --out "$out/$algo" >/dev/null
  col=$(head -1 "$out/$algo/runs.csv" | tr ',' '\n' | grep -n '^elapsed_s$' | cut -d: -f1)
  tail -n +2 "$out/$algo/runs.csv" | cut -d, -f"$col" | median > "$out/$algo.median"
done
OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 "$venv/bin/python" scripts/mealpy/ffa_rastrigin.py "$runs" > "$out/mealpy.txt"
cut -d' ' -f1 "$out/mealpy.txt" | median > "$out/mealpy.median"

amfa=$(cat "$out/amfa.median"); fa=$(cat "$out/fa.median"); mp=$(cat "$out/mealpy.median")
echo "Rastrigin-30, 60,000 evaluations, population 40, $runs runs each, median seconds per run:"
echo "  MEALPY 3.0.3 FFA.OriginalFFA  $mp  (best costs: $(cut -d' ' -f2 "$out/mealpy.txt" | tr '\n' ' '))"
echo "  tidepath amfa                 $amfa"
echo "  tidepath fa                   $fa"
awk -v m="$mp" -v a="$amfa" -v f="$fa" 'BEGIN { printf "  MEALPY / amfa = %.0fx, MEALPY / fa = %.0fx\n", m / a, m / f }'
