#!/usr/bin/env bash
# Builds the `tidepath` Python wheel (crates/tidepath-py) with maturin, installs it into a
# virtual environment and runs its pytest suite (issue #36). Exits non-zero on any failure.
#
#   bash scripts/test_python.sh                  # venv in target/py-venv, reused between runs
#   bash scripts/test_python.sh --install-only   # only the venv and its Python packages
#
# Environment: TIDEPATH_PY_VENV (venv folder), TIDEPATH_PY_PROFILE (cargo profile of the
# wheel, default `dev`: the settings `cargo test` uses, so the wheel reuses the crates the test
# command compiled; see Cargo.toml and crates/tidepath-py/Cargo.toml), TIDEPATH_PY_EXTRAS=0 to
# skip the optional packages (pandas, dask[distributed]; their tests then skip, saying why).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
target=${CARGO_TARGET_DIR:-$root/target}
venv=${TIDEPATH_PY_VENV:-$target/py-venv}
profile=${TIDEPATH_PY_PROFILE:-dev}

if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
py="$venv/bin/python"
"$py" -m pip install -q --disable-pip-version-check "maturin>=1.9,<2" numpy pytest mypy matplotlib
if [ "${TIDEPATH_PY_EXTRAS:-1}" != 0 ]; then
  "$py" -m pip install -q --disable-pip-version-check pandas "dask[distributed]" \
    || echo "warning: pandas / dask[distributed] not installed: their tests skip" >&2
fi
# `--install-only`: only the virtual environment and its packages (.ci/run fetches them while
# cargo builds: the download is network-bound, the build CPU-bound).
[ "${1:-}" = "--install-only" ] && exit 0

# The CLI the tests compare against, from the same tree: a no-op after the README's
# `cargo test --workspace`, which builds it (`cargo build -p tidepath-cli` would compile most
# dependencies again: built alone, they get other features than in the workspace's test build).
cargo test -q --locked --workspace --no-run
export TIDEPATH_CLI="$target/debug/tidepath"

wheels=$(mktemp -d)
trap 'rm -rf "$wheels"' EXIT
(cd crates/tidepath-py && "$venv/bin/maturin" build --locked --profile "$profile" --out "$wheels" --interpreter "$py" -q)
"$py" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheels"/tidepath-*.whl

# From outside the source tree, so the installed wheel is what is imported.
cd "$wheels"
"$py" -m pytest -q -p no:cacheprovider "$root/crates/tidepath-py/tests"

# The example: its types checked strictly against the shipped stubs, then run (it draws a PNG,
# compares three planners and, with dask, repeats the sweep on a local cluster).
"$py" -m mypy --strict --no-incremental "$root/examples/python/plan_demo.py"
"$py" "$root/examples/python/plan_demo.py" --out "$wheels/plan_demo.png" >/dev/null
test -s "$wheels/plan_demo.png"
