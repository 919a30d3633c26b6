#!/usr/bin/env bash
# tests/fuzz/run.sh BUILD_DIR SECONDS: runs the libFuzzer harnesses built by `make fuzz`, each for
# SECONDS, from the repository root, on a corpus seeded from data/ and tests/ (the corpus grows
# in BUILD_DIR/corpus_*). A crash leaves its input in BUILD_DIR/artifacts/; copy it to
# tests/fuzz/regressions/ (scene inputs as *.ini, table inputs as *.csv) so that
# tests/test_fuzz_regressions.sh feeds it to the binary from then on. Exit status: non-zero when a
# harness found a crash.
set -u
b=${1:?build directory}; secs=${2:-60}
mkdir -p "$b/corpus_scene" "$b/corpus_aero" "$b/artifacts"
cp data/scenes/*.ini tests/hard/*.ini "$b/corpus_scene/" 2>/dev/null
cp data/aero/*.csv "$b/corpus_aero/"
cp tests/fuzz/regressions/*.ini "$b/corpus_scene/" 2>/dev/null
cp tests/fuzz/regressions/*.csv "$b/corpus_aero/" 2>/dev/null
status=0
for h in scene aero; do
    echo "== fuzz_$h for $secs s"
    "$b/fuzz_$h" -max_total_time="$secs" -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$b/artifacts/${h}_" -print_final_stats=1 "$b/corpus_$h" 2>"$b/fuzz_$h.log"
    rc=$?
    grep -E '^#[0-9]+.*(DONE|pulse)|stat::number_of_executed_units|stat::peak_rss' "$b/fuzz_$h.log" | tail -n 3
    if [ $rc -ne 0 ]; then
        echo "fuzz_$h: FOUND A CRASH (exit $rc); see $b/fuzz_$h.log and $b/artifacts/" >&2
        grep -E 'ERROR|SUMMARY|Test unit written' "$b/fuzz_$h.log" | head -n 5 >&2
        status=1
    fi
done
exit $status
