#!/usr/bin/env bash
# Builds the libFuzzer target for the problem-file parser with clang (AddressSanitizer
# and UndefinedBehaviorSanitizer) and runs it for a bounded time (default 60 s), seeded
# with the problem files in fuzz/corpus/. Needs clang-14 and libclang-rt-14-dev.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
command -v clang++ >/dev/null || { echo "fuzz.sh: needs clang: apt-get install clang-14 libclang-rt-14-dev" >&2; exit 1; }
out=build-fuzz
mkdir -p "$out" "$out/corpus"
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I. -I/usr/include/eigen3 fuzz/problem_fuzzer.cc problem/problem.cc problem/settings.cc problem/outline.cc -o "$out/problem_fuzzer"
"$out/problem_fuzzer" -max_total_time="$seconds" -print_final_stats=1 -dict=fuzz/problem.dict \
  "$out/corpus" fuzz/corpus
