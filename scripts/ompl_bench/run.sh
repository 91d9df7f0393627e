#!/usr/bin/env bash
# OMPL's RRT* (Debian's libompl-dev, native C++) and tidepath's rrt-star on the same seeded
# random-disc worlds, back to back on this machine. See docs/ompl-benchmark.md.
#
#   scripts/ompl_bench/run.sh [--quick] [--seeds N] [--worlds K] [--iterations N] [--repeat R] [--out DIR]
#                             [--tidepath BIN] [--install-only]
#
# --quick: 1 world, 2 seeds, 2000 iterations, 1 repeat (explicit flags still win). Default:
# 3 worlds, 5 seeds, 10,000 iterations, 3 repeats of every (world, seed) (the table takes each
# one's fastest: the runs are deterministic, only the machine's load varies), DIR =
# target/ompl_bench/results (quick: target/ompl_bench/quick).
# Writes DIR/worlds/ (the scenario TOMLs and the OMPL text worlds), DIR/runs/ (each run's path
# and plan), DIR/results.csv (one row per planner run), DIR/summary.md (the table it prints).
# Build outputs go to target/ompl_bench/build/. Installs libompl-dev with apt-get when missing.
# --tidepath BIN: run this tidepath instead of building a release one (CI passes the test
# build's, already compiled: its times are not release figures). --install-only: only install
# libompl-dev, Eigen and g++ when missing, then stop.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

quick=0 install_only=0
seeds="" worlds="" iterations="" repeat="" out="" tidepath=""
usage() {
    sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    exit "${1:-2}"
}
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) quick=1 ;;
        --seeds) seeds=${2:?--seeds N}; shift ;;
        --worlds) worlds=${2:?--worlds K}; shift ;;
        --iterations) iterations=${2:?--iterations N}; shift ;;
        --repeat) repeat=${2:?--repeat R}; shift ;;
        --out) out=${2:?--out DIR}; shift ;;
        --tidepath) tidepath=${2:?--tidepath BIN}; shift ;;
        --install-only) install_only=1 ;;
        -h|--help) usage 0 ;;
        *) echo "run.sh: unknown argument $1" >&2; usage ;;
    esac
    shift
done
if [ "$quick" = 1 ]; then
    : "${worlds:=1}" "${seeds:=2}" "${iterations:=2000}" "${repeat:=1}" "${out:=$root/target/ompl_bench/quick}"
fi
: "${worlds:=3}" "${seeds:=5}" "${iterations:=10000}" "${repeat:=3}" "${out:=$root/target/ompl_bench/results}"
for v in "$worlds" "$seeds" "$iterations" "$repeat"; do
    case "$v" in ''|*[!0-9]*|0) echo "run.sh: --worlds, --seeds, --iterations and --repeat take positive integers" >&2; exit 2 ;; esac
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
build="$root/target/ompl_bench/build"
mkdir -p "$build"

say() { printf '== %s\n' "$*" >&2; }

# (a) OMPL's headers and library, from Debian's package when they are missing.
find_ompl_include() {
    local h
    for h in /usr/include/ompl*/ompl/geometric/planners/rrt/RRTstar.h; do
        [ -f "$h" ] && { echo "${h%/ompl/geometric/planners/rrt/RRTstar.h}"; return 0; }
    done
    return 1
}
need_pkgs=()
find_ompl_include >/dev/null || need_pkgs+=(libompl-dev libeigen3-dev)
command -v g++ >/dev/null || need_pkgs+=(g++)
if [ ${#need_pkgs[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo=sudo
    say "installing ${need_pkgs[*]} with apt-get"
    $sudo apt-get update -q >&2
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${need_pkgs[@]}" >&2
fi
[ "$install_only" = 1 ] && exit 0
ompl_inc=$(dpkg -L libompl-dev 2>/dev/null | grep '/ompl/geometric/planners/rrt/RRTstar\.h$' | head -n 1 || true)
ompl_inc=${ompl_inc%/ompl/geometric/planners/rrt/RRTstar.h}
[ -n "$ompl_inc" ] || ompl_inc=$(find_ompl_include) || { echo "run.sh: OMPL headers not found after install" >&2; exit 1; }
ompl_version=$(dpkg-query -W -f='${Version}' libompl-dev 2>/dev/null || echo unknown)
eigen_inc=/usr/include/eigen3

# (b) The OMPL program, rebuilt when its source is newer than the binary.
ompl_bin="$build/ompl_rrtstar"
if [ ! -x "$ompl_bin" ] || [ "$here/ompl_rrtstar.cpp" -nt "$ompl_bin" ]; then
    say "compiling ompl_rrtstar.cpp against libompl-dev $ompl_version ($ompl_inc)"
    g++ -O2 -std=c++17 -I"$ompl_inc" -I"$eigen_inc" "$here/ompl_rrtstar.cpp" -o "$ompl_bin" -lompl
fi

# (c) tidepath, release build (or the one given with --tidepath).
if [ -n "$tidepath" ]; then
    [ -x "$tidepath" ] || { echo "run.sh: --tidepath $tidepath is not an executable" >&2; exit 2; }
    tidepath="$(cd "$(dirname "$tidepath")" && pwd)/$(basename "$tidepath")"
    say "using $tidepath (not built here: its times are those of however it was built)"
else
    say "building tidepath (cargo build --release -p tidepath-cli)"
    (cd "$root" && cargo build --release -q -p tidepath-cli)
    tidepath="$root/target/release/tidepath"
fi
have_rrt_star=0
planners=$("$tidepath" planners)
grep -q '^  rrt-star ' <<< "$planners" && have_rrt_star=1

# (d) The worlds: one list of discs per world, written as a tidepath scenario and as text.
say "writing $worlds world(s) to $out/worlds"
if [ "$have_rrt_star" = 1 ]; then
    python3 "$here/make_worlds.py" --worlds "$worlds" --samples "$iterations" --out "$out/worlds"
else
    echo "run.sh: this tidepath has no rrt-star planner (tidepath planners): OMPL side only" >&2
    python3 "$here/make_worlds.py" --worlds "$worlds" --samples "$iterations" --planner-id visibility --no-params \
        --out "$out/worlds"
fi

# The exact shortest path of each world (tidepath's visibility planner), for reference.
optimum_csv="$out/optimum.csv"
echo "world,optimum_m" > "$optimum_csv"
for k in $(seq 1 "$worlds"); do
    "$tidepath" plan "$out/worlds/w$k.toml" --planner visibility --out "$out/worlds/w$k.optimum.json" >/dev/null
    python3 - "$out/worlds/w$k.optimum.json" "w$k" >> "$optimum_csv" <<'EOF'
import json, sys
plan = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]},{plan['missions'][0]['metrics']['length_m']!r}")
EOF
done

# (e, f) Each (world, seed): OMPL and tidepath back to back, the first of the pair alternating.
runs="$out/runs"
mkdir -p "$runs"
results="$out/results.csv"
echo "world,seed,repeat,order,planner,iterations,time_s,length_m,solved,tidepath_verdict,vertices" > "$results"

run_ompl() { # world seed order k_nearest(1: OMPL's default, 0: the radius form)
    local w=$1 s=$2 order=$3 kn=$4 line verdict label=ompl-rrtstar path
    [ "$kn" = 0 ] && label=ompl-rrtstar-radius
    path="$runs/${label}_${w}_s$s.json"
    line=$("$ompl_bin" "$out/worlds/$w.txt" --seed "$s" --iterations "$iterations" --range 1000 --resolution 25 \
        --goal-threshold 1e-6 --k-nearest "$kn" --name "$w" --path-out "$path")
    # world,seed,iterations,time_s,length,solved,exact,tree_states,state_checks
    IFS=, read -r _ _ it t len solved exact verts _ <<< "$line"
    # tidepath's own check of OMPL's path on the scenario: exact segment-disc tests.
    verdict=none
    if [ "$solved" = 1 ]; then
        # (eval exits non-zero on an infeasible path: the verdict says which)
        verdict=$("$tidepath" eval "$out/worlds/$w.toml" "$path" | sed -n 's/^ *verdict: //p' || true)
    fi
    verdict=${verdict%%,*}  # "NOT feasible, 1 violation(s): ..." -> "NOT feasible"
    echo "$w,$s,$r,$order,$label,$it,$t,$len,$exact,${verdict// /_},$verts" >> "$results"
}
run_tidepath() { # world seed order
    local w=$1 s=$2 order=$3 plan
    plan="$runs/tidepath_${w}_s$s.json"
    rm -f "$plan"
    # (plan exits non-zero when the tree did not reach the goal; the plan JSON says so)
    "$tidepath" plan "$out/worlds/$w.toml" --planner rrt-star --samples "$iterations" --seed "$s" --jobs 1 \
        --out "$plan" > "$runs/tidepath_${w}_s$s.txt" || [ -s "$plan" ]
    python3 - "$plan" "$w" "$s,$r" "$order" >> "$results" <<'EOF'
import json, sys
plan = json.load(open(sys.argv[1]))
m = plan['missions'][0]
solved = 1 if plan['feasible'] else 0
print(','.join([sys.argv[2], sys.argv[3], sys.argv[4], 'tidepath-rrt-star', str(plan['samples']),
                repr(plan['elapsed_s']), repr(m['metrics']['length_m']), str(solved), plan['status'],
                str(plan['graph_nodes'])]))
EOF
}

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
total=$((worlds * seeds * repeat))
n=0
# Repeat r is one round over every (world, seed), so the repeats of a run are half a minute or more apart.
for r in $(seq 1 "$repeat"); do
    for k in $(seq 1 "$worlds"); do
        for s in $(seq 1 "$seeds"); do
            n=$((n + 1))
            say "run $n/$total: w$k seed $s (repeat $r)"
            # Three runs back to back: OMPL's default RRTstar (k-nearest), OMPL's radius form,
            # tidepath's rrt-star; the order is reversed from one seed to the next and from one
            # repeat to the next.
            if [ "$have_rrt_star" = 0 ]; then
                run_ompl "w$k" "$s" 1 1
                run_ompl "w$k" "$s" 2 0
            elif [ $(((k + s + r) % 2)) = 1 ]; then
                run_ompl "w$k" "$s" 1 1
                run_ompl "w$k" "$s" 2 0
                run_tidepath "w$k" "$s" 3
            else
                run_tidepath "w$k" "$s" 1
                run_ompl "w$k" "$s" 2 0
                run_ompl "w$k" "$s" 3 1
            fi
        done
    done
done

# (g) The table.
{
    echo "OMPL $ompl_version RRTstar vs tidepath rrt-star: $worlds world(s) x $seeds seed(s) x $repeat repeat(s), $iterations iterations;"
    echo "$(date -u +%Y-%m-%d), $(nproc) cores, $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -n 1); load average $load_before before, $(cut -d\  -f1-3 /proc/loadavg) after"
    echo
    python3 "$here/summarize.py" "$results" "$optimum_csv"
} | tee "$out/summary.md"
say "rows: $results; table: $out/summary.md"
