#!/usr/bin/env bash
# tests/bench/sweep.sh BUILD: the parallel efficiency of `gallop sweep` (issue 18): 200 reduced
# cases (iced_gallop at 20 elements, 60 s each: wind.speed 20 values x conductor.damping_ratio
# 10 values) alone and under `mpirun -n 2`, SWEEP_BENCH_REPEATS times (default 3), each into a
# fresh directory (nothing resumed). Prints BENCH| lines (tests/bench/run.sh puts them in the
# table): the efficiency T1 / (2 T2) and the cases per hour per core, medians of the repeats.
# Wall times on a shared machine are noisy (medians); the work efficiency (CPU seconds of 1 rank
# over those of 2) does not depend on what else runs, but cannot see a rank waiting.
set -eu
build=${1:-build}
gallop=$build/gallop
reps=${SWEEP_BENCH_REPEATS:-3}
if ! command -v mpirun > /dev/null || ! ldd "$gallop" | grep -q libmpi; then
    echo "BENCH|sweep: not measured (no mpirun, or gallop built without MPI)|-|-|make deps, then rebuild|"
    exit 0
fi
tmp=$(mktemp -d /tmp/gallop_bench_sweep_XXXXXX)
trap 'rm -rf "$tmp"' EXIT
mpi=(--oversubscribe)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
args=(data/scenes/iced_gallop.ini --vary wind.speed=3:12.5:0.5 --vary conductor.damping_ratio=0.001:0.01:0.001
      --model reduced --set model.elements=20 --set simulation.duration=60)
wall() { jq .wall_time_s "$1/summary.json"; }
# CPU seconds (user + system) of a command and its children: the work, whatever else runs
TIMEFORMAT='%U %S'
cpu() { { time "$@" > /dev/null 2>&1; } 2>&1 | awk '{ print $1 + $2 }'; }
e=(); r1=(); r2=(); w=()
for i in $(seq "$reps"); do
    c1=$(cpu "$gallop" sweep "${args[@]}" -o "$tmp/one$i")
    c2=$(cpu mpirun "${mpi[@]}" -n 2 "$gallop" sweep "${args[@]}" -o "$tmp/two$i")
    w+=("$(awk -v a="$c1" -v b="$c2" 'BEGIN { printf "%.3f", a / b }')")
    n=$(jq .cases "$tmp/one$i/summary.json")
    t1=$(wall "$tmp/one$i"); t2=$(wall "$tmp/two$i")
    e+=("$(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.3f", a / (2 * b) }')")
    r1+=("$(awk -v n="$n" -v a="$t1" 'BEGIN { printf "%.0f", 3600 * n / a }')")
    r2+=("$(awk -v n="$n" -v b="$t2" 'BEGIN { printf "%.0f", 3600 * n / (2 * b) }')")
    echo "sweep bench $i: $n cases, 1 rank $t1 s ($c1 s CPU), 2 ranks $t2 s ($c2 s CPU)" >&2
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "BENCH|sweep: parallel efficiency, 2 ranks against 1, 200 reduced cases|$(median "${e[@]}")|-|T1 / (2 T2), median of $reps; target >= 0.9 (tests/bench/sweep.sh)|"
echo "BENCH|sweep: work efficiency, CPU of 1 rank over CPU of 2 ranks|$(median "${w[@]}")|-|the same runs: what parallelism adds (MPI, duplicated set-ups), blind to idle ranks|"
echo "BENCH|sweep: cases per hour per core, 1 rank|$(median "${r1[@]}")|cases/h|iced_gallop, 20 elements, 60 s per case, median of $reps|"
echo "BENCH|sweep: cases per hour per core, 2 ranks|$(median "${r2[@]}")|cases/h|the same on mpirun -n 2, median of $reps|"
