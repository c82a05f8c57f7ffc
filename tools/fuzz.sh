#!/usr/bin/env bash
# Fuzzes the scene parser with libFuzzer for SECONDS (default 600), then prints executions and findings.
#   tools/fuzz.sh [SECONDS]     (needs clang and libclang-rt-14-dev; tools/setup.sh installs them)
# Builds tests/fuzz/parser_fuzz in build-fuzz/ (clang, -fsanitize=fuzzer,address,undefined), seeds a corpus from
# scenes/, tests/bad_input/ and tests/fuzz/regressions/, and writes crashes, hangs and leaks to build-fuzz/findings/.
# Copy a finding into tests/fuzz/regressions/ once it is fixed: fuzz_regression_tests replays that folder.
set -euo pipefail

seconds=${1:-600}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
jobs=${FUZZ_BUILD_JOBS:-2}

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DWARDRAY_FUZZ=ON -DWARDRAY_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target parser_fuzz -j "$jobs" >/dev/null

# The corpus keeps what earlier runs found; the seeds are copied in again each time (names are contents).
corpus="$build/corpus"
findings="$build/findings"
mkdir -p "$corpus" "$findings"
for f in "$root"/scenes/*.pov "$root"/scenes/*/*.pov "$root"/tests/bad_input/*.pov "$root"/tests/bad_input/inc/* \
         "$root"/tests/fuzz/regressions/*; do
  [ -f "$f" ] && cp "$f" "$corpus/seed-$(sha1sum "$f" | cut -c1-16)"
done

# A dictionary of the language's keywords and directives helps the mutator build statements.
dict="$build/pov.dict"
{
  grep -o '"[A-Za-z_][A-Za-z_0-9]*"' "$root/parser/keywords.cpp" | sort -u
  for d in declare local include macro end while for if ifdef ifndef else elseif switch case range break \
           fopen read write fclose undef default version debug error warning; do echo "\"#$d\""; done
  for p in '{' '}' '<' '>' '(' ')' '[' ']' ',' ';' '"' '/*' '*/' '//'; do echo "\"$p\""; done
} > "$dict"

before=$(find "$findings" -type f | wc -l)
log="$build/fuzz.log"
started=$SECONDS
set +e
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$build/tests/fuzz/parser_fuzz" "$corpus" -dict="$dict" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -malloc_limit_mb=1024 -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1
status=$?
set -e
elapsed=$((SECONDS - started))

executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
after=$(find "$findings" -type f | wc -l)
# libFuzzer stops at its first crash, hang or leak: then it ran for less than the time asked.
echo "fuzz: ${elapsed} s of ${seconds} s asked, ${executions} executions, libFuzzer exit status ${status}"
echo "fuzz: corpus $(find "$corpus" -type f | wc -l) inputs; findings: $((after - before)) new, ${after} in $findings"
find "$findings" -type f -newer "$dict" -printf '  %f\n'
grep -m3 -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error|SUMMARY' "$log" || true
