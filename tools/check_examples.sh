#!/usr/bin/env bash
# Report: the share of POV-Ray's example scenes that `wardray --check` parses without error, and the top errors;
# then render coverage: the share that parse with no "... is not rendered yet" warning, and what blocks the rest.
# Set CHECK_LIST=1 to also print every failing scene with its first error.
set -u
usage() { echo "usage: $0 WARDRAY_BINARY [EXAMPLES_DIR] [TIMEOUT_SECONDS]" >&2; exit 2; }
[ $# -ge 1 ] || usage
bin=$(realpath "$1")
root=${2:-/usr/share/doc/povray/examples}
limit=${3:-20}
[ -x "$bin" ] || { echo "not executable: $bin" >&2; exit 2; }
results=$(mktemp)
trap 'rm -f "$results"' EXIT

# One line per scene: "ok<TAB>path<TAB>features not rendered (;-separated)" or "fail<TAB>path<TAB>first error line".
while IFS= read -r -d '' scene; do
    dir=$(dirname "$scene")
    err=$(cd "$dir" && timeout "$limit" "$bin" --check "$(basename "$scene")" 2>&1; echo "status=$?")
    status=${err##*status=}
    err=${err%status=*}
    if [ $status -eq 0 ]; then
        missing=$(printf '%s\n' "$err" | grep -o "[^:]* is not rendered yet" | sed 's/ is not rendered yet//; s/^ *//' | sort -u | paste -sd ';')
        printf 'ok\t%s\t%s\n' "$scene" "$missing" >> "$results"
    else
        first=$(printf '%s\n' "$err" | grep -m1 ': error: ')
        [ $status -eq 124 ] && first="error: timed out after ${limit} s"
        [ -z "$first" ] && first="error: exit status $status: $(printf '%s\n' "$err" | head -n 1 | head -c 200)"
        printf 'fail\t%s\t%s\n' "$scene" "$first" >> "$results"
    fi
done < <(find "$root" -name '*.pov' -print0 | sort -z)

/usr/bin/python3 - "$results" <<'PY'
import collections, os, re, sys

def normalise(line):
    # Keep the message, drop "path:line:col: error: ", quoted names, numbers and paths so messages group.
    msg = line.split(": error: ", 1)[1] if ": error: " in line else line
    if msg.startswith("error: "):
        msg = msg[len("error: "):]
    msg = re.sub(r"'[^']*'", "'…'", msg)
    msg = re.sub(r'"[^"]*"', '"…"', msg)
    msg = re.sub(r"(/[\w.+-]+)+", "PATH", msg)
    msg = re.sub(r"\b\d+(\.\d+)?\b", "N", msg)
    return msg.strip()

ok = total = rendered = 0
counts = collections.Counter()
blockers = collections.Counter()
examples = {}
with open(sys.argv[1], encoding="utf-8", errors="replace") as f:
    for row in f:
        parts = row.rstrip("\n").split("\t")
        total += 1
        if parts[0] == "ok":
            ok += 1
            features = [f for f in (parts[2] if len(parts) > 2 else "").split(";") if f]
            rendered += not features
            blockers.update(features)
            continue
        key = normalise(parts[2] if len(parts) > 2 else "")
        counts[key] += 1
        examples.setdefault(key, parts[1])
pct = 100.0 * ok / total if total else 0.0
print(f"example scenes parsed without error: {ok} of {total} ({pct:.1f} %)")
if os.environ.get("CHECK_LIST") == "1":
    with open(sys.argv[1], encoding="utf-8", errors="replace") as f:
        for row in f:
            parts = row.rstrip("\n").split("\t")
            if parts[0] != "ok":
                print("FAIL", parts[1], "|", parts[2] if len(parts) > 2 else "")
print("most frequent first errors:")
for msg, n in counts.most_common(10):
    print(f"  {n:4d}  {msg}   (e.g. {examples[msg]})")
pct = 100.0 * rendered / total if total else 0.0
print(f"example scenes with no 'not rendered yet' warning: {rendered} of {total} ({pct:.1f} %)")
print("what blocks the rest (scenes per feature, most frequent first):")
for feature, n in blockers.most_common(15):
    print(f"  {n:4d}  {feature}")
PY
