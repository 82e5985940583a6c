#!/usr/bin/env bash
# The Python package in CI: installs it into a venv with the README's command
# (`pip install ./crates/python`, maturin fetched from PyPI by pip), then runs its pytest suite
# (crates/python/tests) and the worked example examples/python/aeb_in_the_loop.py.
#
# Usage: scripts/python_check.sh [PYTEST ARGS...]
#        scripts/python_check.sh --install   # only the venv and the test tools (no build, no
#                                            # tests): .ci/run fetches them during its compilation
#   OSCSIM_PY_VENV  the venv (default .venv at the repository root, shared with the OSI check:
#                   the same pinned osi-python decodes the ground truth there).
#   OSCSIM          the oscsim binary the tests compare with (default target/release/oscsim;
#                   .ci/run builds it first).
# Exit status: 0 when the package installs and every test passes; 1 otherwise.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
install_only=0
if [ "${1:-}" = --install ]; then
    install_only=1
fi
venv="${OSCSIM_PY_VENV:-$root/.venv}"
cd "$root"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
py="$venv/bin/python"
"$py" -m pip install --quiet --upgrade pip
# The test tools: pytest, the official OSI bindings (pinned as in scripts/osi_check.sh),
# pandas for the data-frame paths.
"$py" -m pip install --quiet pytest "osi-python==3.8.0" pandas
# Ray for the batch driver's Ray backend (tests/test_batch.py runs it on a local cluster). Where
# PyPI has no ray wheel for this platform the test is skipped with the reason, not failed.
if ! ray_log="$("$py" -m pip install --quiet ray 2>&1)"; then
    export OSCSIM_SKIP_RAY="ray does not install on this platform: $(printf '%s' "$ray_log" | tail -n 1)"
    echo "python_check: $OSCSIM_SKIP_RAY" >&2
fi
if [ "$install_only" = 1 ]; then
    exit 0
fi
# The README's install command.
"$py" -m pip install --quiet ./crates/python
export OSCSIM="${OSCSIM:-$root/target/release/oscsim}"
# Run from outside the source tree so that the installed package, not crates/python/python,
# is imported.
cd "$root/crates/python/tests"
"$py" -m pytest -q "$@" .
