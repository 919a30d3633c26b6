#!/usr/bin/env bash
# test_hard_scenes.sh: the hard cases of tests/hard/*.ini through the real binary (issue 8).
# Each scene says in its opening comment what it tests and what must hold. For each: `gallop
# modes` (and `gallop simulate` where the case is dynamic) exits 0 with finite numbers in
# summary.json (no null, no nan, no inf) and the case's own property holds. An exit 1 counts as a
# failure unless the case says it may refuse (run_may_refuse: then the refusal must give its reason
# and write nothing). Never a crash (exit >= 128) or a hang (timeout).
# Run from the repository root (scenes name their conductor from data/conductors.csv).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch hard
H=tests/hard

# Full-model runs: src/full/dynamics.c leaves the velocity of the clamped nodes in its Newton iterate
# (v1) uninitialised (malloc) and the aerodynamic loads read it, so full-model results depend on
# heap garbage (reported with issue 8). Until that is fixed, full runs get zero-filled fresh heap
# memory (glibc: perturb byte 255 fills with 0; ASan: fill byte 0); `known_dynamics_bug` below
# shows whether the bug is still there.
zero_heap() {
    GLIBC_TUNABLES=glibc.malloc.perturb=255 \
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}malloc_fill_byte=0:max_malloc_fill_size=268435456" "$@"
}

# json NUMBER-KEY FILE: the first value of "KEY": in FILE
json() { grep -o "\"$1\": [^,}]*" "$2" | head -n 1 | sed 's/.*: //'; }
# finite FILE: no null, nan or inf among the values
finite() { ! grep -Eqi '(: |\[|, )(null|-?nan|-?inf)' "$1"; }
# rel_close A B TOL: |A - B| <= TOL |B|
rel_close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN{d=a-b; if(d<0)d=-d; if(b<0)b=-b; exit !(d<=t*b)}'; }

# run NAME CMD SCENE [ARGS...]: runs gallop CMD with a time limit into $tmp/NAME; sets rc.
# Classifies the exit: 0 (then summary.json must be finite), 1 only where the caller set
# may_refuse=PATTERN (the reason stderr must give), anything else is a failure of the test.
# Returns 0 when the caller should check the case.
run() {
    local name=$1 cmd=$2 scene=$3; shift 3
    local t0=$SECONDS
    timeout 120 "$GALLOP" "$cmd" "$scene" -o "$tmp/$name" "$@" >"$tmp/$name.out" 2>"$tmp/$name.err"
    rc=$?
    local dt=$((SECONDS - t0))
    if [ $rc -eq 124 ]; then bad "$name: hangs (killed after 120 s)"; return 1; fi
    if [ $rc -ge 128 ]; then bad "$name: crashed (exit $rc): $(tail -n 3 "$tmp/$name.err")"; return 1; fi
    if [ $rc -eq 1 ]; then
        if [ "${may_refuse:-}" = "" ]; then
            bad "$name: exit 1 where an answer is due: $(tail -n 1 "$tmp/$name.err" | cut -c1-150)"
        elif [ -s "$tmp/$name.err" ] && [ ! -e "$tmp/$name/summary.json" ] \
            && grep -qi -- "$may_refuse" "$tmp/$name.err"; then
            ok "$name: refuses with its reason (exit 1): $(tail -n 1 "$tmp/$name.err" | cut -c1-150)"
        else
            bad "$name: exit 1 without the reason '$may_refuse', or with partial output"
        fi
        return 1
    fi
    if [ $rc -ne 0 ]; then bad "$name: exit $rc: $(tail -n 2 "$tmp/$name.err")"; return 1; fi
    if [ ! -s "$tmp/$name/summary.json" ]; then bad "$name: exit 0 but no summary.json"; return 1; fi
    if finite "$tmp/$name/summary.json"; then
        ok "$name: exit 0, summary.json finite (${dt} s)"
    else
        bad "$name: summary.json has non-finite values: $(grep -Ein 'null|nan|inf' "$tmp/$name/summary.json" | head -n 3 | tr '\n' ' ')"
        return 1
    fi
    return 0
}

m=$(awk -F, '$1=="Drake"{print $3}' data/conductors.csv)
ith=$(awk -F, '$1=="Drake"{print $7}' data/conductors.csv)
# first frequency of FAMILY (or FAMILY,SYMMETRY) in modes.csv
first_f() { awk -F, -v f="$1" -v s="${2:-}" 'NR>1 && $2==f && (s=="" || $3==s){print $4; exit}' "$3"; }
string_f() { awk -v H="$1" -v m="$2" -v L="$3" 'BEGIN{printf "%.9g", sqrt(H/m)/(2*L)}'; }

# ---- statics and modes ----
for s in taut slack; do
    want=$(awk '/^sag *=/{print $3}' "$H/$s.ini")
    if run "$s" modes "$H/$s.ini"; then
        got=$(json sag_m "$tmp/$s/summary.json")
        rel_close "$got" "$want" 1e-3 && ok "$s: sag $got m (asked $want m), H $(json horizontal_tension_n "$tmp/$s/summary.json") N" \
            || bad "$s: sag $got m, asked $want m"
    fi
done

if run steep_incline modes "$H/steep_incline.ini"; then
    got=$(json horizontal_tension_n "$tmp/steep_incline/summary.json")
    rel_close "$got" 28000 1e-6 && ok "steep_incline: H $got N, sag $(json sag_m "$tmp/steep_incline/summary.json") m" \
        || bad "steep_incline: H $got N, asked 28000 N"
fi

for s in inextensible no_bending fine_mesh; do
    if run "$s" modes "$H/$s.ini"; then
        f=$(first_f horizontal "" "$tmp/$s/modes.csv"); g=$(string_f 28000 "$m" 300)
        rel_close "$f" "$g" 5e-3 && ok "$s: first horizontal $f Hz, string theory $g Hz" \
            || bad "$s: first horizontal $f Hz vs string theory $g Hz"
    fi
done

for s in torsion_soft torsion_stiff; do
    gj=$(awk '/^torsional_stiffness *=/{print $3}' "$H/$s.ini")
    if run "$s" modes "$H/$s.ini"; then
        f=$(first_f torsional "" "$tmp/$s/modes.csv"); g=$(string_f "$gj" "$ith" 300)
        rel_close "$f" "$g" 1e-2 && ok "$s: first torsional $f Hz, torsional string $g Hz" \
            || bad "$s: first torsional $f Hz vs torsional string $g Hz"
    fi
done

if run irvine_crossover modes "$H/irvine_crossover.ini"; then
    ea=$(awk '/^axial_stiffness *=/{print $3}' "$H/irvine_crossover.ini")
    lam=$(awk -v m="$m" -v ea="$ea" 'BEGIN{L=300; H=28000; g=9.80665; s=m*g*L*L/(8*H);
          Le=L*(1+8*(s/L)^2); printf "%.4g", (m*g*L/H)^2*L/(H*Le/ea)}')
    fs=$(first_f vertical symmetric "$tmp/irvine_crossover/modes.csv")
    fa=$(first_f vertical antisymmetric "$tmp/irvine_crossover/modes.csv")
    if [ -n "$fs" ] && [ -n "$fa" ] && rel_close "$fs" "$fa" 1e-2; then
        ok "irvine_crossover: lambda^2 = $lam (4 pi^2 = 39.48): symmetric $fs Hz, antisymmetric $fa Hz"
    else
        bad "irvine_crossover: lambda^2 = $lam: symmetric '$fs' Hz, antisymmetric '$fa' Hz"
    fi
fi

# the dynamic scenes have modes too: every frequency positive and increasing, and at least the
# modes the scene selects
for s in strong_wind wind_reversal twist_accumulation long_run huge_time_step; do
    if run "$s.modes" modes "$H/$s.ini"; then
        awk -F, 'NR>1 {if (!($4 > 0) || $4 < prev) exit 1; prev=$4; n++} END{exit !(n >= 3)}' "$tmp/$s.modes/modes.csv" \
            && ok "$s: $(($(wc -l < "$tmp/$s.modes/modes.csv") - 1)) modes, positive and ordered, first $(awk -F, 'NR==2{print $4}' "$tmp/$s.modes/modes.csv") Hz" \
            || bad "$s: modes.csv has a zero, negative or unordered frequency"
    fi
done

# ---- dynamics ----
# strong wind: both models finish with a bounded amplitude
for model in reduced full; do
    if zero_heap run "strong_wind.$model" simulate "$H/strong_wind.ini" --model "$model" --set simulation.duration=20; then
        a=$(json vertical "$tmp/strong_wind.$model/summary.json")
        awk -v a="$a" 'BEGIN{exit !(a < 20)}' && ok "strong_wind $model: vertical p-p $a m, twist p-p $(json twist_amplitude_deg "$tmp/strong_wind.$model/summary.json") deg" \
            || bad "strong_wind $model: vertical p-p $a m"
    fi
done

# wind reversal: the mean horizontal displacement at mid-span changes sign
for model in reduced full; do
    if [ $model = full ]; then set -- --set simulation.duration=30 --set simulation.wind_reverse_time=15; else set --; fi
    if zero_heap run "wind_reversal.$model" simulate "$H/wind_reversal.ini" --model "$model" "$@"; then
        tr=$(awk -F' *= *' '/^wind_reverse_time/{print $2+0}' "$H/wind_reversal.ini")
        [ $model = full ] && tr=15
        read -r before after < <(awk -F, -v tr="$tr" 'NR>1 && $1>tr/3 && $1<tr {a+=$2; na++}
             NR>1 && $1>tr+tr/3 {b+=$2; nb++} END{printf "%.4g %.4g\n", a/na, b/nb}' "$tmp/wind_reversal.$model/trace.csv")
        awk -v a="$before" -v b="$after" 'BEGIN{exit !(a > 0 && b < 0)}' \
            && ok "wind_reversal $model: horizontal mean $before m before, $after m after the reversal at $tr s" \
            || bad "wind_reversal $model: horizontal mean $before m before, $after m after"
    fi
done

# twist past 360 deg: the full model; the reduced model may refuse, its self-check giving the reason
if zero_heap run twist_accumulation.full simulate "$H/twist_accumulation.ini" --model full; then
    tw=$(awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i ~ /_twist_deg$/) c[i]=1}
         NR>1{for(i in c){v=$i<0?-$i:$i; if(v>mx)mx=v}} END{printf "%.1f", mx}' "$tmp/twist_accumulation.full/trace.csv")
    awk -v t="$tw" 'BEGIN{exit !(t > 360)}' && ok "twist_accumulation full: max |twist| $tw deg" \
        || bad "twist_accumulation full: max |twist| only $tw deg"
fi
# The reduced model (issue 13: coupling recomputed from the rod, self-checked) may refuse, its
# self-check finding the residual grown in the torsional family (exit 1, the family and the keys
# named, nothing written); when it follows, it must turn past 360 deg as the full model does. Both
# are read the same way, the largest |twist| of trace.csv: the twist p-p over the summary's steady
# window is not a reproducible figure of this case (the twist wanders by whole turns): the full
# model's own reads 575 deg, 585 with the reference BLAS, 183 with simulation.newton_tolerance =
# 1e-6 and 692 at 96 elements (measured 2026-11-24), so no bound on it tells a right reduced run
# from a wrong one.
if may_refuse="residual grew to .* in the torsional family" run twist_accumulation.reduced simulate "$H/twist_accumulation.ini" --model reduced; then
    tw=$(awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i ~ /_twist_deg$/) c[i]=1}
         NR>1{for(i in c){v=$i<0?-$i:$i; if(v>mx)mx=v}} END{printf "%.1f", mx}' "$tmp/twist_accumulation.reduced/trace.csv")
    awk -v t="$tw" 'BEGIN{exit !(t > 360)}' && ok "twist_accumulation reduced: max |twist| $tw deg" \
        || bad "twist_accumulation reduced: exit 0 with max |twist| only $tw deg where the full model turns past 360"
fi

# one hour of the reduced model: no drift. The steady vertical amplitude (RMS at mid-span) of
# the first ten minutes of steady galloping (20-30 min) and of the last ten (50-60 min) agree
# within 5 % (the attractor still wanders a little after 20 min: 1.062 vs 1.050 m with -O2, 1.088
# vs 1.050 m in the sanitizer build); the mean within 10 %; and the last two
# ten-minute windows (40-50, 50-60 min) agree within 1 % in both.
if run long_run simulate "$H/long_run.ini"; then
    read -r r1 m1 r3 m3 r2 m2 < <(awk -F, 'NR>1 {w=-1; if($1>=1200 && $1<1800) w=1; if($1>=2400 && $1<3000) w=3;
         if($1>=3000) w=2; if(w>0){s[w]+=$3; ss[w]+=$3*$3; n[w]++}}
         END{for(w=1;w<=3;w++){m=s[w]/n[w]; printf "%.5g %.5g ", sqrt(ss[w]/n[w]-m*m), m} print ""}' \
         "$tmp/long_run/trace.csv")
    end=$(tail -n 1 "$tmp/long_run/trace.csv" | cut -d, -f1)
    if rel_close "$r2" "$r1" 0.05 && rel_close "$m2" "$m1" 0.10 && rel_close "$r2" "$r3" 0.01 \
        && rel_close "$m2" "$m3" 0.01 && awk -v e="$end" 'BEGIN{exit !(e > 3599)}'; then
        ok "long_run: to t = $end s; vertical RMS $r1 m (20-30 min), $r3 m (40-50), $r2 m (50-60); mean $m1, $m3, $m2 m"
    else
        bad "long_run: to t = $end s; vertical RMS $r1, $r3, $r2 m; mean $m1, $m3, $m2 m"
    fi
fi

# a full-model time step far too large: adapted (or refused), the answer as with a sound step
if zero_heap run huge_time_step simulate "$H/huge_time_step.ini" --model full; then
    h=$(json time_step_s "$tmp/huge_time_step/summary.json")
    a=$(json vertical "$tmp/huge_time_step/summary.json")
    if zero_heap run huge_time_step.ref simulate "$H/huge_time_step.ini" --model full --set simulation.time_step=0; then
        a0=$(json vertical "$tmp/huge_time_step.ref/summary.json")
        awk -v h="$h" 'BEGIN{exit !(h <= 0.05)}' && rel_close "$a" "$a0" 0.05 \
            && ok "huge_time_step: 5 s asked, $h s used; vertical p-p $a m vs $a0 m with gallop's step" \
            || bad "huge_time_step: $h s used; vertical p-p $a m vs $a0 m with gallop's step"
    else
        bad "huge_time_step: the reference run failed"
    fi
fi

# ---- full-model results must not depend on what fresh heap memory holds (a bug once): fill it
# with 0xfe bytes (a huge negative double) instead of zeros.
known_dynamics_bug() {
    local a b
    GLIBC_TUNABLES=glibc.malloc.perturb=1 ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}malloc_fill_byte=254" \
        timeout 120 "$GALLOP" simulate "$H/huge_time_step.ini" --model full --set simulation.duration=10 \
        -o "$tmp/garbage" >/dev/null 2>"$tmp/garbage.err"
    a=$(json vertical "$tmp/garbage/summary.json" 2>/dev/null)
    zero_heap timeout 120 "$GALLOP" simulate "$H/huge_time_step.ini" --model full --set simulation.duration=10 \
        -o "$tmp/zeroed" >/dev/null 2>&1
    b=$(json vertical "$tmp/zeroed/summary.json" 2>/dev/null)
    if [ -n "$a" ] && [ "$a" = "$b" ]; then
        ok "full model independent of uninitialised heap memory"
    else
        bad "full model depends on uninitialised heap memory: garbage heap gives" \
             "'${a:-$(tail -n 1 "$tmp/garbage.err" | cut -c1-120)}', zeroed heap '$b'"
    fi
}
known_dynamics_bug

# ---- a full-model step tied to a coarse output interval: time_step = output_interval = 10 s
# would report the galloping (about 0.25 Hz) at the sampling's alias frequency: it must be
# refused or adapted.
known_coarse_step() {
    local f
    zero_heap timeout 120 "$GALLOP" simulate "$H/huge_time_step.ini" --model full --set simulation.duration=1000 \
        --set simulation.time_step=10 --set simulation.output_interval=10 -o "$tmp/coarse" >/dev/null 2>"$tmp/coarse.err"
    local rc=$?
    f=$(json frequency_hz "$tmp/coarse/summary.json" 2>/dev/null)
    if [ $rc -eq 1 ] || [ $rc -eq 2 ]; then
        ok "time_step = output_interval = 10 s refused: $(tail -n 1 "$tmp/coarse.err" | cut -c1-120)"
    elif [ $rc -eq 0 ] && awk -v f="$f" 'BEGIN{exit !(f > 0.2 && f < 0.3)}'; then
        ok "time_step = output_interval = 10 s adapted: $f Hz"
    else
        bad "time_step = output_interval = 10 s: exit $rc, galloping frequency '$f' Hz (true about 0.25 Hz)"
    fi
}
known_coarse_step

finish
