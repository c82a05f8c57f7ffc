#!/usr/bin/env bash
# Report: can every standard POV-Ray .inc be #included by a one-line scene without an error (wardray --check)?
set -u
usage() { echo "usage: $0 WARDRAY_BINARY [INCLUDE_DIR]" >&2; exit 2; }
[ $# -ge 1 ] || usage
bin=$(realpath "$1")
incdir=${2:-/usr/share/povray-3.7/include}
[ -x "$bin" ] || { echo "not executable: $bin" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

total=0
ok=0
failures=""
for inc in "$incdir"/*.inc; do
    name=$(basename "$inc")
    total=$((total + 1))
    printf '#include "%s"\n' "$name" > "$work/one.pov"
    # Only errors count; warnings (assumed_gamma, features not rendered) are fine.
    # A subshell, so a crash is reported through the exit status and not as shell noise.
    status=$( (timeout 20 "$bin" --check "$work/one.pov" > /dev/null 2> "$work/err"); echo $? ) 2> /dev/null
    if [ "$status" -eq 0 ]; then
        ok=$((ok + 1))
    else
        first=$(grep -m1 ': error: ' "$work/err" || true)
        [ $status -eq 124 ] && first="timed out after 20 s"
        [ -z "$first" ] && first="exit status $status: $(head -n 1 "$work/err" | head -c 200)"
        failures+="  $name: $first"$'\n'
    fi
done
echo "includes parsed without error: $ok of $total"
[ -n "$failures" ] && printf 'failures:\n%s' "$failures"
exit 0
