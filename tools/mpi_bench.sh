#!/bin/bash
# Wall time of 1 rank against 2 ranks (1 thread each) on POV-Ray's cornell.pov with its radiosity (256x256) and
# on a direct-light scene (advanced/woodbox.pov, 640x480 +A0.3), the two rank counts alternating; prints each run,
# the medians and their ratio (wall clock, and wardray's own clock from --stats), and checks that the images are
# byte-identical. Usage: tools/mpi_bench.sh BIN [RUNS]
# It also measures the machine's own ceiling for two processes: a plain single-thread render alone, and two of them
# started together (the slower one's wall time). 2 x alone / pair is the speed-up that perfectly independent halves
# of the same work would get on these two cores, which slow each other down when both are busy.
set -euo pipefail
bin=$(realpath "${1:?usage: tools/mpi_bench.sh path/to/wardray [runs]}")
runs=${2:-5}
examples=/usr/share/doc/povray/examples
mpirun="mpirun --oversubscribe --allow-run-as-root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A args=(
  [cornell]="$examples/radiosity/cornell.pov +W256 +H256 +WT1 -A"
  [woodbox]="$examples/advanced/woodbox.pov +W640 +H480 +A0.3 +WT1"
)
for ((r = 1; r <= runs; r++)); do
  for scene in cornell woodbox; do
    for np in 1 2; do
      rm -f "$work/stats.json"
      start=$(date +%s.%N)
      # shellcheck disable=SC2086
      $mpirun -np $np "$bin" ${args[$scene]} -o "$work/$scene$np.png" --stats "$work/stats.json" > /dev/null 2>&1
      echo "$scene $np $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" | tee -a "$work/times"
      # wardray's own clock (--stats' total_seconds: from its start to its exit, without mpirun's launch and wind-up).
      own=$(sed -n 's/^ *"total_seconds": *\([0-9.eE+-]*\).*/\1/p' "$work/stats.json")
      echo "$scene own$np ${own:-nan}" >> "$work/times"
    done
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$bin" ${args[$scene]} -o "$work/${scene}A.png" > /dev/null 2>&1
    echo "$scene alone $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" | tee -a "$work/times"
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$bin" ${args[$scene]} -o "$work/${scene}P1.png" > /dev/null 2>&1 &
    # shellcheck disable=SC2086
    "$bin" ${args[$scene]} -o "$work/${scene}P2.png" > /dev/null 2>&1
    wait
    echo "$scene pair $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" | tee -a "$work/times"
  done
done
median() { awk -v s="$1" -v n="$2" '$1 == s && $2 == n { print $3 }' "$work/times" | sort -g |
  awk '{ a[NR] = $1 } END { print NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
for scene in cornell woodbox; do
  cmp -s "$work/${scene}1.png" "$work/${scene}2.png" && same=byte-identical || same=DIFFERENT
  m1=$(median "$scene" 1)
  m2=$(median "$scene" 2)
  printf "%s: 1 rank %.2f s, 2 ranks %.2f s (medians), speed-up %.2f, images %s\n" "$scene" "$m1" "$m2" \
    "$(awk -v a="$m1" -v b="$m2" 'BEGIN { print a / b }')" "$same"
  o1=$(median "$scene" own1)
  o2=$(median "$scene" own2)
  printf "%s: on wardray's own clock (without mpirun's start and end) 1 rank %.2f s, 2 ranks %.2f s, speed-up %.2f\n" \
    "$scene" "$o1" "$o2" "$(awk -v a="$o1" -v b="$o2" 'BEGIN { print a / b }')"
  ma=$(median "$scene" alone)
  mp=$(median "$scene" pair)
  printf "%s: plain render alone %.2f s, two at once %.2f s (medians): the machine's ceiling for 2 processes %.2f\n" \
    "$scene" "$ma" "$mp" "$(awk -v a="$ma" -v b="$mp" 'BEGIN { print 2 * a / b }')"
done
