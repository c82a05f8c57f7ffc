#!/bin/bash
# Wall time of 1 rank against 2 ranks (1 thread each) on POV-Ray's cornell.pov with its radiosity (256x256) and
# on a direct-light scene (advanced/woodbox.pov, 640x480 +A0.3), the two rank counts alternating; prints each run,
# the medians and their ratio, and checks that the images are byte-identical. Usage: tools/mpi_bench.sh BIN [RUNS]
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
      start=$(date +%s.%N)
      # shellcheck disable=SC2086
      $mpirun -np $np "$bin" ${args[$scene]} -o "$work/$scene$np.png" > /dev/null 2>&1
      echo "$scene $np $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" | tee -a "$work/times"
    done
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
done
