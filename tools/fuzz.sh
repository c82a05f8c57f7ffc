#!/usr/bin/env bash
# Fuzzes with libFuzzer for SECONDS (default 600), then prints executions and findings.
#   tools/fuzz.sh [SECONDS] [parser|render]     (needs clang and libclang-rt-14-dev; tools/setup.sh installs them)
# parser (the default) fuzzes tests/fuzz/parser_fuzz, the parser alone; render fuzzes tests/fuzz/render_fuzz, the
# whole pipeline (parse, build, render 8x6 with radiosity when asked, every pixel finite).
# Builds the target (tests/fuzz/parser_fuzz.cpp or tests/app/render_fuzz.cpp) in build-fuzz/ (clang, -fsanitize=fuzzer,address,undefined), seeds a corpus from scenes/,
# POV-Ray's example scenes (FUZZ_EXAMPLES, the files under 16 KB), tests/bad_input/ and the regression folders, and
# writes crashes, hangs and leaks to build-fuzz/findings[-render]/. Everything runs under `nice -n 19` (the machine
# is shared: the fuzzer takes only idle CPU), in libFuzzer's fork mode, which records a finding and goes on, so
# one run of an hour collects every finding of that hour.
# Copy a finding into tests/fuzz/regressions/ (parser) or tests/fuzz/render_regressions/ (render) once it is
# fixed: fuzz_regression_tests and render_fuzz_regression_tests replay those folders.
set -euo pipefail

seconds=${1:-600}
target=${2:-parser}
case "$target" in
  parser) suffix="" ;;
  render) suffix="-render" ;;
  *) echo "fuzz.sh: the target is parser or render, not '$target'" >&2; exit 2 ;;
esac
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
jobs=${FUZZ_BUILD_JOBS:-2}

CC=clang CXX=clang++ nice -n 19 cmake -S "$root" -B "$build" -DWARDRAY_FUZZ=ON -DWARDRAY_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
nice -n 19 cmake --build "$build" --target "${target}_fuzz" -j "$jobs" >/dev/null

# The corpus keeps what earlier runs found; the seeds are copied in again each time (names are contents).
corpus="$build/corpus$suffix"
findings="$build/findings$suffix"
mkdir -p "$corpus" "$findings"
for f in "$root"/scenes/*.pov "$root"/scenes/*/*.pov "$root"/tests/bad_input/*.pov "$root"/tests/bad_input/inc/* \
         "$root"/tests/fuzz/regressions/* "$root"/tests/fuzz/render_regressions/*; do
  [ -f "$f" ] && cp "$f" "$corpus/seed-$(sha1sum "$f" | cut -c1-16)"
done
examples=${FUZZ_EXAMPLES:-/usr/share/povray-3.7/scenes}
if [ -d "$examples" ]; then
  find -L "$examples" -name '*.pov' -size -16k | while read -r f; do
    cp "$f" "$corpus/seed-$(sha1sum "$f" | cut -c1-16)"
  done
fi

# A dictionary of the language's keywords and directives helps the mutator build statements.
dict="$build/pov$suffix.dict"
{
  grep -o '"[A-Za-z_][A-Za-z_0-9]*"' "$root/parser/keywords.cpp" | sort -u
  for d in declare local include macro end while for if ifdef ifndef else elseif switch case range break \
           fopen read write fclose undef default version debug error warning; do echo "\"#$d\""; done
  for p in '{' '}' '<' '>' '(' ')' '[' ']' ',' ';' '"' '/*' '*/' '//'; do echo "\"$p\""; done
} > "$dict"

before=$(find "$findings" -type f | wc -l)
log="$build/fuzz$suffix.log"
started=$SECONDS
set +e
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  nice -n 19 "$build/tests/fuzz/${target}_fuzz" "$corpus" -dict="$dict" -max_total_time="$seconds" -max_len=8192 \
  -timeout=20 -rss_limit_mb=2048 -malloc_limit_mb=1024 -artifact_prefix="$findings/" -print_final_stats=1 \
  -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 >"$log" 2>&1
status=$?
set -e
elapsed=$((SECONDS - started))

# Fork mode prints "#EXECUTIONS: cov: ..." lines; the last one holds the total.
executions=$(grep -oE '^#[0-9]+: ' "$log" | tail -1 | tr -dc 0-9)
[ -n "$executions" ] || executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
after=$(find "$findings" -type f | wc -l)
# Fork mode goes on after a crash, hang or leak; a run shorter than asked means the fuzzer itself failed.
echo "fuzz: ${elapsed} s of ${seconds} s asked, ${executions} executions, libFuzzer exit status ${status}"
echo "fuzz: corpus $(find "$corpus" -type f | wc -l) inputs; findings: $((after - before)) new, ${after} in $findings"
find "$findings" -type f -newer "$dict" -printf '  %f\n'
grep -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error|SUMMARY|deadly signal' "$log" | sort | uniq -c | head -20 || true
