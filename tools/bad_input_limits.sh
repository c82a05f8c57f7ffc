#!/usr/bin/env bash
# Measures every case of tests/bad_input/ with /usr/bin/time -v: exit status, wall and CPU (user + system) time and
# peak resident memory,
# run as bad_input_tests runs it (+W32 +H24 -A --max-loop-iterations 200000 and the case's NAME.args, in an empty
# folder), and prints a Markdown table with the slowest and largest cases and the totals.
#   tools/bad_input_limits.sh [WARDRAY] > table.md        (default WARDRAY: build/wardray)
# A case passes when it exits with status 1 within 5 s of CPU time and 500 MB, writing nothing; the last line says how
# many did. (CPU time, as bad_input_tests holds it: on a loaded shared machine the wall time is several times more.)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
wardray=$(realpath "${1:-$root/build/wardray}")
corpus="$root/tests/bad_input"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rows="$work/rows.tsv"
: > "$rows"
for scene in "$corpus"/*.pov; do
  name=$(basename "$scene" .pov)
  extra=""
  [ -f "$corpus/$name.args" ] && extra=$(tr '\n' ' ' < "$corpus/$name.args")
  mkdir -p "$work/run"
  set +e
  # shellcheck disable=SC2086 # the .args words are separate switches
  (cd "$work/run" && /usr/bin/time -v -o "$work/time.txt" "$wardray" "$scene" +W32 +H24 -A \
      --max-loop-iterations 200000 $extra >/dev/null 2>"$work/err.txt")
  set -e
  status=$(sed -n 's/^\s*Exit status: //p' "$work/time.txt")
  [ -n "$status" ] || status=$(sed -n 's/^Command terminated by signal /signal /p' "$work/time.txt")
  wall=$(sed -n 's/^\s*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt" |
         awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; printf "%.2f", s }')
  kb=$(sed -n 's/^\s*Maximum resident set size (kbytes): //p' "$work/time.txt")
  cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { printf "%.2f", s }' "$work/time.txt")
  left=$(find "$work/run" -mindepth 1 | wc -l)
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$status" "$wall" "$((kb / 1024))" "$left" "$cpu" >> "$rows"
  rm -rf "$work/run"
done

total=$(wc -l < "$rows")
pass=$(awk -F'\t' '$2 == 1 && $6 < 5 && $4 < 500 && $5 == 0' "$rows" | wc -l)
echo "The slowest and the largest cases:"
echo
echo "| case | exit | CPU s | wall s | peak MB |"
echo "|---|---:|---:|---:|---:|"
{ sort -t$'\t' -k6,6gr "$rows" | head -8; sort -t$'\t' -k4,4nr "$rows" | head -8; } | sort -u |
  sort -t$'\t' -k6,6gr | awk -F'\t' '{ printf "| %s | %s | %s | %s | %s |\n", $1, $2, $6, $3, $4 }'
awk -F'\t' -v n="$total" '{ c += $6; w += $3; if ($6 > mc) mc = $6; if ($3 > mw) mw = $3; if ($4 > mm) mm = $4 }
  END { printf "\n%d cases: CPU time %.1f s in all, at most %.2f s (wall %.1f s in all, at most %.2f s); peak resident memory at most %d MB\n", n, c, mc, w, mw, mm }' "$rows"
awk -F'\t' '$2 != 1 || $6 >= 5 || $4 >= 500 || $5 != 0 { printf "NOT WITHIN BOUNDS: %s (exit %s, CPU %s s, %s MB, %s files left)\n", $1, $2, $6, $4, $5 }' "$rows"
echo
echo "$pass of $total cases exit with status 1 within 5 s of CPU time and 500 MB, writing nothing"
