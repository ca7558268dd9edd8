#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with Debian's clang, ASan and UBSan in $BUILD (default
# build-fuzz), then runs each for FUZZ_SECONDS (default 180) or FUZZ_RUNS executions, one at a time
# (-jobs=1), from its seed and regression corpora into a working corpus $BUILD/corpus/<target>.
# Prints per target: executions, coverage (edges), corpus size and crashes; crash inputs are left in
# $BUILD/crashes/<target>/ for tests/fuzz/regressions/<target>/. Usage: fuzz.sh [target...]
set -euo pipefail
BUILD=${BUILD:-build-fuzz}
FUZZ_SECONDS=${FUZZ_SECONDS:-180}
FUZZ_RUNS=${FUZZ_RUNS:--1}
JOBS=${JOBS:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(gltf shadow_settings command_line image shader)

CC=clang CXX=clang++ cmake -S "$root" -B "$BUILD" -DPENUMBRA_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  ${CMAKE_FLAGS:-} --log-level=WARNING >/dev/null
cmake --build "$BUILD" -j "$JOBS" --target "${targets[@]/#/penumbra_fuzz_}"

summary=()
for target in "${targets[@]}"; do
  corpus="$BUILD/corpus/$target" crashes="$BUILD/crashes/$target"
  mkdir -p "$corpus" "$crashes"
  log="$BUILD/fuzz-$target.log"
  # libFuzzer stops at a corpus folder that does not exist: a target without regressions yet has none.
  corpora=("$corpus")
  for extra in "$root/tests/fuzz/seeds/$target" "$root/tests/fuzz/regressions/$target"; do
    [ -d "$extra" ] && corpora+=("$extra")
  done
  dict=()
  [ -f "$root/tests/fuzz/dictionaries/$target.dict" ] && dict=(-dict="$root/tests/fuzz/dictionaries/$target.dict")
  set +e
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "$BUILD/fuzz/penumbra_fuzz_$target" "${corpora[@]}" \
    "${dict[@]}" -jobs=1 -workers=1 -max_total_time="$FUZZ_SECONDS" -runs="$FUZZ_RUNS" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$crashes/" >"$log" 2>&1
  status=$?
  set -e
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo 0)
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  found=$(find "$crashes" -type f | wc -l)
  line="$target: $runs executions, coverage $coverage edges, corpus $(find "$corpus" -type f | wc -l) files, $found crash inputs (exit $status; log $log)"
  echo "fuzz: $line"
  summary+=("$line")
done
printf 'fuzz summary:\n'; printf '  %s\n' "${summary[@]}"
