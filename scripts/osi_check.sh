#!/usr/bin/env bash
# Check OSI ground-truth traces with the official OSI Python bindings.
#
# Usage: scripts/osi_check.sh TRACE.osi|TRACE.mcap ...
#        scripts/osi_check.sh --install   # only the venv and the packages (.ci/run fetches
#                                         # them during its compilation)
#   Creates or reuses a venv (OSI_CHECK_VENV, default .venv at the repository root),
#   installs osi-python==3.8.0 and asam-osi-utilities==0.4.0 into it, then runs
#   ../shared/tools/osi_check.py on every trace (OSI_CHECK_TOOL overrides the path)
#   and, for .mcap traces, crates/osi/scripts/compare_schema.py, which compares the
#   embedded osi3 schema with the official one field by field.
#   Extra checker options (e.g. --expect-entities N) go in OSI_CHECK_ARGS.
# Exit status: 0 when every check passed; 1 when a check failed; 2 on bad usage;
#   3 when the Python packages could not be installed (prints "OSI CHECK NOT RUN: ...")
#   unless OSI_CHECK_OPTIONAL=1, in which case it exits 0 after the same loud message.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="${OSI_CHECK_VENV:-$root/.venv}"
tool="${OSI_CHECK_TOOL:-$root/../shared/tools/osi_check.py}"
schema_tool="$root/crates/osi/scripts/compare_schema.py"

if [ "$#" -eq 0 ]; then
    echo "usage: $0 TRACE.osi|TRACE.mcap ..." >&2
    exit 2
fi

not_run() {
    echo "##################################################################" >&2
    echo "OSI CHECK NOT RUN: $*" >&2
    echo "##################################################################" >&2
    if [ "${OSI_CHECK_OPTIONAL:-0}" = "1" ]; then
        exit 0
    fi
    exit 3
}

[ -f "$tool" ] || not_run "checker not found at $tool"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv" || not_run "cannot create a Python venv at $venv (is python3-venv installed?)"
fi
if ! "$venv/bin/python" -c "import osi3, osi_utilities, mcap" 2>/dev/null; then
    "$venv/bin/python" -m pip install --quiet "osi-python==3.8.0" "asam-osi-utilities==0.4.0" \
        || not_run "pip could not install osi-python==3.8.0 asam-osi-utilities==0.4.0"
fi
"$venv/bin/python" -c "import osi3, osi_utilities, mcap" \
    || not_run "the OSI Python packages do not import after installation"
if [ "$1" = --install ]; then
    exit 0
fi

status=0
for trace in "$@"; do
    echo "== $trace"
    # shellcheck disable=SC2086  # OSI_CHECK_ARGS is a list of options
    "$venv/bin/python" "$tool" "$trace" ${OSI_CHECK_ARGS:-} || status=1
    case "$trace" in
        *.mcap) "$venv/bin/python" "$schema_tool" "$trace" || status=1 ;;
    esac
done
exit "$status"
