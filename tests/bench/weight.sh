#!/usr/bin/env bash
# weight.sh: the static load responses of the reduced basis (rom.h o.weight_vector, o.wind_vector;
# BENCHMARKS.md "The weight's and the mean wind's static responses in the reduced basis") measured
# on ordinary runs: `gallop compare` (300 s, model.on_invalid = warn) on the five limit-cycle spans of
# tests/rom/ at 100 and 125 elements and data/scenes/iced_gallop.ini at 80, for each variant of
# VARIANTS (GALLOP_ROM_LOADVEC: 0 neither, 1 K0^-1 W, 2 K0^-1 F_mean, 3 both). The switch is not in
# the shipped program: a copy of the tree with tests/bench/weight_switch.patch applied to
# src/run/integrator_rom.c is built in OUT/src. Then the table (tests/bench/weight_table.py): per
# case and variant the signed errors against the full model of frequency, vertical, horizontal and
# twist p-p (compare's headline), largest support tension over the run, residual_max, basis, valid,
# the reduced run's wall time. Reduced CPU: `gallop simulate` per variant, alternating, REPEAT times.
# Usage: tests/bench/weight.sh [OUT]   (default out/weight; 15-30 min on 2 loaded cores)
set -eu
out=${1:-out/weight}
VARIANTS=${VARIANTS:-"0 1 2 3"} REPEAT=${REPEAT:-3}
mkdir -p "$out/src"
git archive HEAD | tar -x -C "$out/src"
(cd "$out/src" && patch -s -p1 < tests/bench/weight_switch.patch && make -s build/gallop >/dev/null)
g=$out/src/build/gallop
cases="data/scenes/iced_gallop.ini:80"
for e in 100 125; do
    for s in bersimis_350_crescent cardinal_500_stiff_gj condor_150_taut_dshape drake_200_level_dshape falcon_400_incline80; do
        cases="$cases tests/rom/$s.ini:$e"
    done
done
for v in $VARIANTS; do
    for c in $cases; do
        f=${c%%:*} e=${c##*:} d=$out/lv$v/$(basename "$f" .ini)-$e
        mkdir -p "$d"
        GALLOP_ROM_LOADVEC=$v "$g" compare "$f" -o "$d" --set model.elements="$e" --set simulation.duration=300 \
            --set model.on_invalid=warn > "$d/stdout" 2> "$d/stderr" || echo "$d: exit $?"
    done
done
python3 tests/bench/weight_table.py "$out" $(for v in $VARIANTS; do echo lv$v; done)
for r in $(seq "$REPEAT"); do
    for c in tests/rom/condor_150_taut_dshape.ini:100 tests/rom/drake_200_level_dshape.ini:125 data/scenes/iced_gallop.ini:80; do
        for v in $VARIANTS; do
            f=${c%%:*} e=${c##*:}
            GALLOP_ROM_LOADVEC=$v /usr/bin/time -f "%U %S" -o "$out/cpu.t" "$g" simulate "$f" -o "$out/cpu-run" \
                --set model.elements="$e" --set simulation.duration=300 --set model.on_invalid=warn > /dev/null 2>&1
            echo "$(basename "$f" .ini) $e variant $v repeat $r CPU user+sys $(cat "$out/cpu.t") load $(cut -d' ' -f1 /proc/loadavg)"
        done
    done
done
