#!/usr/bin/env bash
# speed_ab.sh: two gallop binaries' speed over the span set of tests/rom/, as spanset.sh measures
# it (issue 13), the two run alternately span by span so that both see the same load: for every
# span and mesh, `gallop simulate --model full|reduced` of SPEED_T s (default 300) and of 10 s,
# each a process under `perf stat -e task-clock` (CPU ms of the process; spanset.sh's /usr/bin/time
# has 10 ms steps, too coarse for a 10-s reduced run); per simulated second (CPU(SPEED_T) -
# CPU(10)) / (SPEED_T - 10). Prints one row per binary, span and mesh: full and reduced CPU of the
# whole SPEED_T-s process, the whole-process ratio, the per-simulated-second ratio; then the
# medians per binary and mesh. A run that fails (exit 1: the reduced model refused) is left out
# of the medians, as spanset.sh leaves out the spans whose runs did not all finish.
# Usage: tests/bench/speed_ab.sh BIN_A BIN_B [OUT]   Environment: MESHES ("100 125"), SPEED_T,
# SPANS (default every tests/rom/*.ini). One BLAS thread; run it under nice.
set -u
a=$1 b=$2 out=${3:-/tmp/speed_ab}
MESHES=${MESHES:-"100 125"} SPEED_T=${SPEED_T:-300} SPANS=${SPANS:-$(ls tests/rom/*.ini)}
export OPENBLAS_NUM_THREADS=1
mkdir -p "$out"
cpu() { # BIN SCENE MODEL ELEMENTS T -> CPU ms, or "fail"
  local f=$out/stat.$$
  if perf stat -x, -e task-clock -o "$f" "$1" simulate "$2" --model "$3" -o "$out/run" --set model.elements="$4" \
     --set simulation.duration="$5" >/dev/null 2>&1; then awk -F, '/task-clock/ {print $1}' "$f"; else echo fail; fi
}
rows=$out/rows.txt
: > "$rows"
for s in $SPANS; do
  for e in $MESHES; do
    for tag in A B; do
      bin=$a; [ $tag = B ] && bin=$b
      f1=$(cpu "$bin" "$s" full "$e" "$SPEED_T") f0=$(cpu "$bin" "$s" full "$e" 10)
      r1=$(cpu "$bin" "$s" reduced "$e" "$SPEED_T") r0=$(cpu "$bin" "$s" reduced "$e" 10)
      echo "$tag $(basename "$s" .ini) $e $f1 $f0 $r1 $r0" | tee -a "$rows" | awk -v T="$SPEED_T" '{
        if ($4 == "fail" || $5 == "fail" || $6 == "fail" || $7 == "fail") { print $0, "(a run failed)"; next }
        printf "%s %-26s %4d full %8.0f ms reduced %7.0f ms whole %6.2fx per-sim-s %6.2fx\n", $1, $2, $3, $4, $6, $4 / $6, ($4 - $5) / ($6 - $7) }'
    done
  done
done
echo "medians (runs that all finished):"
for tag in A B; do
  for e in $MESHES; do
    awk -v t=$tag -v e=$e '$1 == t && $3 == e && $4 != "fail" && $5 != "fail" && $6 != "fail" && $7 != "fail" {
      n++; w[n] = $4 / $6; p[n] = ($4 - $5) / ($6 - $7) }
      function med(x, n,   i, j, y) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { y = x[i]; x[i] = x[j]; x[j] = y }
        return n % 2 ? x[(n + 1) / 2] : 0.5 * (x[n / 2] + x[n / 2 + 1]) }
      END { printf "%s %4d elements, %d spans: whole process %.2fx, per simulated second %.2fx\n", t, e, n, med(w, n), med(p, n) }' "$rows"
  done
done
