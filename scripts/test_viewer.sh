#!/usr/bin/env bash
# The 3-D viewer in a real browser: writes the views of a demo plan,
# salish-strait, a fleet plan and a simulation, and opens each in headless Chromium with
# software WebGL (scripts/view_test/check_views.mjs): it must render, raise no JavaScript
# error, make no request, redraw when the time slider moves, and give non-blank screenshots.
# First the checker shows on small broken pages that it fails them (`--self-test`).
#
#   bash scripts/test_viewer.sh
#
# Environment: TIDEPATH_BIN (the CLI; default: target/debug/tidepath, built in the test
# profile), VIEW_SHOTS (screenshot folder, default target/view-test/shots), TIDEPATH_CHROMIUM
# (browser, default /usr/bin/chromium: Debian's chromium, installed with apt-get if missing).
#
#   bash scripts/test_viewer.sh --install-only   # only the browser, Node and the npm packages
#                                                # (.ci/run fetches them while cargo builds)
set -euo pipefail
cd "$(dirname "$0")/.."

install_only=false
[ "${1:-}" = "--install-only" ] && install_only=true

if $install_only; then
  :
elif [ -n "${TIDEPATH_BIN:-}" ]; then
  bin=$TIDEPATH_BIN
else
  # A no-op after the README's `cargo test --workspace`, which builds the CLI (the CLI tests run
  # it). Not `cargo build -p tidepath-cli`: built alone, the CLI's dependencies get other
  # features than in the workspace's test build, and Cargo compiles most of them again.
  cargo test -q --locked --workspace --no-run
  bin=${CARGO_TARGET_DIR:-target}/debug/tidepath
fi
$install_only || [ -x "$bin" ] || { echo "test_viewer: no tidepath binary at $bin" >&2; exit 1; }

as_root=""
[ "$(id -u)" -ne 0 ] && as_root=sudo
missing=()
[ -x "${TIDEPATH_CHROMIUM:-/usr/bin/chromium}" ] || missing+=(chromium)
command -v node >/dev/null || missing+=(nodejs npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "test_viewer: installing ${missing[*]} with apt-get"
  $as_root apt-get update -q >/dev/null
  $as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
fi

npm ci --prefix scripts/view_test --no-audit --no-fund --loglevel=error >/dev/null
$install_only && exit 0

d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT

# Runs the CLI; exit 1 (a plan that is not feasible) is accepted, the view must still be written.
gen() {
  local out=$1 rc=0
  shift
  "$bin" "$@" >"$d/log" 2>&1 || rc=$?
  if [ "$rc" -gt 1 ] || [ ! -s "$out" ]; then
    echo "test_viewer: \`tidepath $*\` exited $rc without writing $out:" >&2
    cat "$d/log" >&2
    exit 1
  fi
}
gen "$d/demo.html" plan demo --view "$d/demo.html"
gen "$d/salish-strait.html" view salish-strait -o "$d/salish-strait.html"
gen "$d/fleet.html" plan fleet-rendezvous --planner pso --iterations 30 --view "$d/fleet.html"
gen "$d/simulate.html" simulate coastal-traffic --view "$d/simulate.html"

node scripts/view_test/check_views.mjs --self-test --shots "${VIEW_SHOTS:-target/view-test/shots}" \
  "$d/demo.html" "$d/salish-strait.html" "$d/fleet.html" "$d/simulate.html"
