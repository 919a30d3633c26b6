#!/usr/bin/env bash
# test_sweep.sh: `gallop sweep` (issue 18): bad --vary is exit 2 naming the key and the allowed
# range; a small grid gives the same sweep.csv (every column but wall_time_s) alone and on 2 MPI
# ranks; an interrupted sweep resumes (finished cases skipped, the same result); a changed scene
# is not resumed; --continuation runs up and then down the first key.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch sweep
scene=$here/../data/scenes/iced_gallop.ini
# small and short: 16 elements, 40 s of the full model per case
small=(--model full --set model.elements=16 --set simulation.duration=40 --set model.modes_vertical=2
       --set model.modes_horizontal=1)
strip() { cut -d, -f1-"$(($(head -1 "$1" | tr ',' '\n' | wc -l) - 1))" "$1"; }   # all but wall_time_s
# Open MPI's own leaks under SAN=1 (tests/lsan-openmpi.supp). Its components are unloaded at
# MPI_Finalize, so the frames of their allocations cannot be named: the full (slow) unwinding
# reaches the frames of libmpi below them, which the suppressions name. gallop's leaks still count.
openmpi_sanitizers

# ---- bad input: exit 2, the key and the allowed range named ----
expect2() {
  local what=$1 pat=$2; shift 2
  "$GALLOP" sweep "$scene" "$@" -o "$tmp/bad" > "$tmp/out" 2> "$tmp/err"; local rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$pat" "$tmp/err"; then ok "$what: exit 2, '$pat'"
  else bad "$what: exit $rc: $(head -2 "$tmp/err")"; fi
}
expect2 "value out of range" "allowed: 0 <= speed <= 80" --vary wind.speed=4,-3
expect2 "unknown key" "wind.spd" --vary wind.spd=1,2
expect2 "range against its step" "allowed: --vary section.key=v1" --vary wind.speed=5:1:1
expect2 "zero step" "does not go from" --vary wind.speed=1:5:0
expect2 "no --vary" "no --vary" --model full
expect2 "key twice" "given twice" --vary wind.speed=1,2 --vary wind.speed=3
[ ! -e "$tmp/bad/sweep.csv" ] && ok "bad input writes nothing" || bad "bad input wrote sweep.csv"

# ---- a 3 x 2 grid alone ----
grid=(--vary wind.speed=2:10:4 --vary conductor.damping_ratio=0.002,0.01)
"$GALLOP" sweep "$scene" "${grid[@]}" "${small[@]}" -o "$tmp/one" > "$tmp/one.out" 2> "$tmp/one.err"; rc=$?
rows=$(($(wc -l < "$tmp/one/sweep.csv" 2>/dev/null || echo 1) - 1))
[ $rc -eq 0 ] && [ "$rows" = 6 ] && ok "3 x 2 grid: 6 rows" || bad "3 x 2 grid: exit $rc, $rows rows: $(tail -2 "$tmp/one.err")"
head -1 "$tmp/one/sweep.csv" | grep -q '^wind.speed,conductor.damping_ratio,branch,vertical_pp_m,horizontal_pp_m,twist_pp_deg,frequency_hz,tension_max_n,onset_speed_m_s,valid,wall_time_s$' \
  && ok "sweep.csv columns" || bad "sweep.csv header: $(head -1 "$tmp/one/sweep.csv")"
# the grid's first key fastest; the amplitude grows with the wind (onset ~3.4 m/s) at the low damping
awk -F, 'NR == 2 && $1 == 2 && $2 == 0.002 { a = $4 } NR == 4 && $1 == 10 && $2 == 0.002 { b = $4 }
         END { exit !(b > 5 * a && a > 0) }' "$tmp/one/sweep.csv" \
  && ok "the amplitude at 10 m/s is above 5x that at 2 m/s" || bad "amplitudes: $(sed -n '2p;4p' "$tmp/one/sweep.csv")"
# the onset: the same for both speeds of one damping, higher with more damping
awk -F, 'NR > 1 { o[$1 "," $2] = $9 } END { exit !(o["2,0.002"] == o["10,0.002"] && o["2,0.01"] > o["2,0.002"]) }' \
  "$tmp/one/sweep.csv" && ok "onset_speed_m_s: per span, higher with more damping" || bad "onset column"
[ "$(jq -r '.cases, .computed, .resumed, .failed' "$tmp/one/summary.json" | tr '\n' ' ')" = "6 6 0 0 " ] \
  && ok "summary.json totals" || bad "summary totals: $(jq -c '[.cases, .computed, .resumed, .failed]' "$tmp/one/summary.json")"
jq -e '.galloping_from["wind.speed"] | length == 2' "$tmp/one/summary.json" > /dev/null \
  && ok "galloping_from: a line per damping value along wind.speed" || bad "galloping_from"

# ---- the same on 2 ranks ----
mpi=()
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
if ! command -v mpirun > /dev/null; then
  bad "mpirun missing (Debian openmpi-bin: make deps)"
elif ! ldd "$GALLOP" 2>/dev/null | grep -q libmpi; then
  bad "gallop is built without MPI (Debian libopenmpi-dev: make deps, then rebuild)"
else
  mpirun --oversubscribe "${mpi[@]}" -n 2 "$GALLOP" sweep "$scene" "${grid[@]}" "${small[@]}" -o "$tmp/two" \
    > "$tmp/two.out" 2> "$tmp/two.err"; rc=$?
  [ $rc -eq 0 ] && [ "$(jq .ranks "$tmp/two/summary.json")" = 2 ] && ok "mpirun -n 2: exit 0, 2 ranks" \
    || bad "mpirun -n 2: exit $rc: $(tail -3 "$tmp/two.err")"
  cmp -s <(strip "$tmp/one/sweep.csv") <(strip "$tmp/two/sweep.csv") \
    && ok "1 and 2 ranks: the same sweep.csv, digit for digit" || bad "1 and 2 ranks differ"
  [ "$(grep -c 'cases done' "$tmp/two.err")" -ge 1 ] && ok "rank 0 shows the progress" || bad "no progress lines"
fi

# ---- an interrupted sweep resumes ----
"$GALLOP" sweep "$scene" "${grid[@]}" "${small[@]}" -o "$tmp/int" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do
  [ "$(ls "$tmp/int/cases" 2>/dev/null | grep -c '\.case$')" -ge 2 ] && break
  sleep 0.1
done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
done_before=$(ls "$tmp/int/cases" | grep -c '\.case$')
[ ! -e "$tmp/int/sweep.csv" ] && [ "$done_before" -ge 2 ] && [ "$done_before" -lt 6 ] \
  && ok "killed after $done_before of 6 cases" || bad "kill: $done_before cases, sweep.csv $(ls "$tmp/int")"
"$GALLOP" sweep "$scene" "${grid[@]}" "${small[@]}" -o "$tmp/int" > "$tmp/int.out" 2> "$tmp/int.err"; rc=$?
[ $rc -eq 0 ] && [ "$(jq .resumed "$tmp/int/summary.json")" = "$done_before" ] \
  && [ "$(jq .computed "$tmp/int/summary.json")" = $((6 - done_before)) ] \
  && ok "the rerun skips the $done_before finished cases" || bad "resume: exit $rc, $(jq -c '[.computed,.resumed]' "$tmp/int/summary.json")"
cmp -s <(strip "$tmp/one/sweep.csv") <(strip "$tmp/int/sweep.csv") \
  && ok "the resumed sweep.csv is the uninterrupted one" || bad "resumed sweep.csv differs"
# a changed scene is not resumed
"$GALLOP" sweep "$scene" "${grid[@]}" "${small[@]}" --set simulation.duration=41 -o "$tmp/int" > /dev/null 2>&1
[ "$(jq .resumed "$tmp/int/summary.json")" = 0 ] && ok "a changed scene: nothing resumed" \
  || bad "changed scene resumed $(jq .resumed "$tmp/int/summary.json") cases"

# ---- continuation: up and then down the first key ----
"$GALLOP" sweep "$scene" --vary wind.speed=2:6:2 --continuation "${small[@]}" -o "$tmp/cont" > /dev/null 2> "$tmp/cont.err"
[ "$(cut -d, -f1,2 "$tmp/cont/sweep.csv" | tr '\n' ' ')" = "wind.speed,branch 2,up 4,up 6,up 4,down 2,down " ] \
  && ok "--continuation: rows up then down" || bad "--continuation rows: $(cut -d, -f1,2 "$tmp/cont/sweep.csv" | tr '\n' ' ')"
# the way down starts from the motion reached at the top: more motion at 2 m/s than on the way up
awk -F, '$1 == 2 && $2 == "up" { u = $3 } $1 == 2 && $2 == "down" { d = $3 } END { exit !(d > 2 * u) }' \
  "$tmp/cont/sweep.csv" && ok "--continuation: the way down carries the motion of the top" \
  || bad "continuation amplitudes: $(cut -d, -f1-3 "$tmp/cont/sweep.csv" | tr '\n' ' ')"

# ---- a galloping hysteresis loop (tests/sweep/hysteresis.ini: a subcritical section, the linear
# onset at 7.5 m/s, galloping kept down to about 4.9 m/s by harmonic balance), full model ----
"$GALLOP" sweep "$here/sweep/hysteresis.ini" --vary wind.speed=4:10:2 --continuation --model full -o "$tmp/hyst" \
  > /dev/null 2> "$tmp/hyst.err"; rc=$?
up=$(jq '.galloping_from["wind.speed"][] | select(.branch == "up") | .galloping_from' "$tmp/hyst/summary.json")
down=$(jq '.galloping_from["wind.speed"][] | select(.branch == "down") | .galloping_from' "$tmp/hyst/summary.json")
[ $rc -eq 0 ] && [ "$up" = 10 ] && [ "$down" = 6 ] \
  && ok "hysteresis: galloping from 10 m/s on the way up, down to 6 m/s on the way down" \
  || bad "hysteresis: exit $rc, up $up, down $down: $(cut -d, -f1-3 "$tmp/hyst/sweep.csv" | tr '\n' ' ')"
# at 6 m/s: at rest on the way up, galloping (> 0.3 m) on the way down; none at 4 m/s either way
awk -F, '$1 == 6 && $2 == "up" { u = $3 } $1 == 6 && $2 == "down" { d = $3 } $1 == 4 && $2 == "down" { z = $3 }
         END { exit !(u < 0.01 && d > 0.3 && z < 0.01) }' "$tmp/hyst/sweep.csv" \
  && ok "hysteresis: 6 m/s still up, galloping down; 4 m/s still" || bad "hysteresis amplitudes"

finish
