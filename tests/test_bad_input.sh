#!/usr/bin/env bash
# test_bad_input.sh: bad input through the real binary (issue 8), one case per class: every
# scene key with a malformed or out-of-range value, absurd sizes, wrong aerodynamic tables for
# [ice] aero_table, unreadable files. For `gallop modes` and `gallop simulate` alike: exit 2, the
# message names the file, the line and the key, and nothing is written in the -o directory.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch bad_input

cp data/aero/iced_d_shape.csv "$tmp/good.csv"
# a valid iced scene with wind: every command would run it; line numbers matter below
base() {
    cat <<EOF
; base scene for test_bad_input.sh
[span]
length = 200
horizontal_tension = 25000
[conductor]
name = Drake
[ice]
mass_per_length = 0.6
aero_table = ${1:-good.csv}
[wind]
speed = 10
[model]
elements = 20
[simulation]
duration = 10
[effects]
[output]
EOF
}

# scene NAME SECTION "key = value" [TABLE]: the base scene with the line put right after
# [SECTION] (replacing the key there if the base has it; a new section goes at the end).
# Prints the line number of the new line.
scene() {
    local name=$1 sec=$2 kv=$3 table=${4:-good.csv}
    local key=${kv%%=*}; key=${key%% *}
    base "$table" | awk -v sec="[$sec]" -v kv="$kv" -v key="$key" '
        /^\[/ { ins = ($0 == sec) }
        ins && $1 == key && /=/ { next }
        { print; n++ }
        $0 == sec { print kv; n++; at = n; done = 1 }
        END { if (!done) { print sec; print kv; at = n + 2 } print at > "/dev/stderr" }' \
        >"$tmp/$name.ini" 2>"$tmp/$name.line"
    cat "$tmp/$name.line"
}

# refused NAME SCENE LINE WORD [ARGS...]: both commands exit 2, stderr names SCENE (with :LINE
# when LINE > 0; "--set:" instead when LINE < 0) and WORD, no -o directory is made.
refused() {
    local name=$1 sc=$2 line=$3 word=$4; shift 4
    local cmd why=""
    for cmd in modes simulate; do
        local out="$tmp/out_${name}_$cmd"
        timeout 60 "$GALLOP" "$cmd" "$sc" -o "$out" "$@" >"$tmp/$name.out" 2>"$tmp/$name.err"
        local rc=$?
        local where="$sc"
        [ "$line" -gt 0 ] && where="$sc:$line:"
        [ "$line" -lt 0 ] && where="--set:"
        if [ $rc -ne 2 ]; then why="$why $cmd: exit $rc;"
        elif ! grep -qF -- "$where" "$tmp/$name.err"; then why="$why $cmd: message lacks '$where';"
        elif ! grep -qF -- "$word" "$tmp/$name.err"; then why="$why $cmd: message lacks '$word';"
        fi
        [ -e "$out" ] && why="$why $cmd: wrote $out;"
        [ -s "$tmp/$name.out" ] && why="$why $cmd: wrote to stdout;"
    done
    if [ -z "$why" ]; then ok "$name: exit 2: $(head -n 1 "$tmp/$name.err" | cut -c1-140)"
    else bad "$name:$why $(head -n 1 "$tmp/$name.err" | cut -c1-200)"; fi
}

# key CASE SECTION "key = value" [WORD]: one bad scene value
key() {
    local name=$1 sec=$2 kv=$3 word=${4:-}
    local k=${kv%%=*}; k=${k%% *}
    local line; line=$(scene "$name" "$sec" "$kv")
    refused "$name" "$tmp/$name.ini" "$line" "${word:-$k}"
}

# ---- the base scene itself is good (else every refusal below proves nothing) ----
base >"$tmp/base.ini"
if timeout 60 "$GALLOP" modes "$tmp/base.ini" -o "$tmp/base_out" >/dev/null 2>"$tmp/base.err" &&
   timeout 60 "$GALLOP" simulate "$tmp/base.ini" -o "$tmp/base_sim" >/dev/null 2>>"$tmp/base.err"; then
    ok "the base scene runs (modes and simulate)"
else
    bad "the base scene fails: $(cat "$tmp/base.err")"
fi

# ---- [span] ----
key span_length_negative    span "length = -3"
key span_length_zero        span "length = 0"
key span_length_text        span "length = abc"
key span_length_huge        span "length = 1e7"
key span_hdiff_huge         span "height_difference = 6000"
key span_hdiff_nan          span "height_difference = nan"
key span_tension_negative   span "horizontal_tension = -1"
key span_tension_inf        span "horizontal_tension = inf"
scene span_two_specs span "sag = 5" >/dev/null   # the second of the two is the one refused
refused span_two_specs "$tmp/span_two_specs.ini" 5 "sag (line 3)"
key span_ulength_negative   span "unstretched_length = -5"
key span_rts_one            span "tension_rts = 1"
key span_temperature_cold   span "temperature = -300"
scene span_tension_and_rts span "tension_rts = 0.2" >/dev/null  # horizontal_tension now line 5
refused span_tension_and_rts "$tmp/span_tension_and_rts.ini" 5 "tension_rts (line 3)"
scene span_stringing_and_tension stringing "horizontal_tension = 20000" >/dev/null
refused span_stringing_and_tension "$tmp/span_stringing_and_tension.ini" 19 "horizontal_tension (line 4)"
printf '[span]\nlength = 200\n[stringing]\nsag = 5\n[conductor]\nname = Drake\n' >"$tmp/nostringtemp.ini"
refused stringing_no_temperature "$tmp/nostringtemp.ini" 4 "[stringing] temperature"
key stringing_temperature_alone stringing "temperature = 15" "stringing condition"
# a taut span shorter than the chord is accepted down to chord / 1.01; 197 m on the 200 m chord is
# 1.5 % strain, past a conductor's breaking strain (issue 14)
refused span_ulength_overstretched "$tmp/base.ini" -1 "breaking strain" --set span.unstretched_length=197
key span_end_twist_bad      span "end_twist = sometimes"
key span_unknown_key        span "lenght = 200"
key span_no_equals          span "length 200" "length"
# ---- [conductor] ----
key cond_name_unknown       conductor "name = NoSuchWire" "NoSuchWire"
key cond_diameter_zero      conductor "diameter = 0"
key cond_diameter_huge      conductor "diameter = 0.5"
key cond_mass_negative      conductor "mass_per_length = -1"
key cond_ea_zero            conductor "axial_stiffness = 0"
key cond_ea_huge            conductor "axial_stiffness = 1e11"
key cond_ei_negative        conductor "bending_stiffness = -1"
key cond_gj_zero            conductor "torsional_stiffness = 0"
key cond_polar_zero         conductor "polar_inertia = 0"
key cond_zeta_one           conductor "damping_ratio = 1"
key cond_zeta_negative      conductor "damping_ratio = -0.1"
key cond_unknown_key        conductor "colour = grey"
# ---- [ice] ----
key ice_mass_negative       ice "mass_per_length = -1"
key ice_ecc_huge            ice "eccentricity = 0.6"
key ice_polar_negative      ice "polar_inertia = -1"
key ice_attack_huge         ice "attack_angle = 200"
key ice_table_missing       ice "aero_table = nosuch.csv"
key ice_unknown_key         ice "colour = white"
key ice_thickness_negative  ice "thickness = -0.01"
key ice_density_huge        ice "density = 2000"
printf '[span]\nlength = 200\nhorizontal_tension = 25000\n[conductor]\nname = Drake\n[ice]\nthickness = 0.01\nshape = no_such_shape\n' >"$tmp/noshape.ini"
refused ice_shape_unknown "$tmp/noshape.ini" 8 "no_such_shape"
scene ice_thickness_and_mass ice "thickness = 0.01" >/dev/null   # mass_per_length now line 9
refused ice_thickness_and_mass "$tmp/ice_thickness_and_mass.ini" 9 "thickness (line 8)"
scene ice_shape_and_table ice "shape = iced_d_shape" >/dev/null  # aero_table now line 10
refused ice_shape_and_table "$tmp/ice_shape_and_table.ini" 10 "shape (line 8)"
# ---- [wind] ----
key wind_speed_negative     wind "speed = -1"
key wind_speed_huge         wind "speed = 100"
key wind_yaw_huge           wind "yaw = 200"
key wind_rho_zero           wind "air_density = 0"
key wind_turbulence_bad     wind "turbulence = gusty"
key wind_intensity_huge     wind "intensity = 2"
key wind_coherence_zero     wind "coherence_decay = 0"
key wind_seed_negative      wind "seed = -1"
key wind_seed_fraction      wind "seed = 1.5"
key wind_seed_huge          wind "seed = 99999999999999999999"
key wind_unknown_key        wind "gust = 3"
key wind_height_negative    wind "height = -1"
key wind_terrain_bad        wind "terrain = V"
key wind_terrain_no_height  wind "terrain = II" "height"
scene wind_basic_and_speed wind "basic_speed = 20" >/dev/null   # speed now line 12
refused wind_basic_and_speed "$tmp/wind_basic_and_speed.ini" 12 "basic_speed (line 11)"
key wind_vertical_no_field  wind "vertical_turbulence = on"
key wind_vertical_key_off  wind "vertical_intensity = 0.05"
key wind_vertical_intens_2 wind "vertical_intensity = 2"
# ---- [effects] ----
key fx_value_bad            effects "gravity = maybe"
key fx_value_number         effects "aero_drag = 2"
key fx_unknown              effects "magnetism = on"
# ---- [model] ----
key model_elements_few      model "elements = 3"
key model_elements_negative model "elements = -5"
key model_elements_1e9      model "elements = 1000000000"
key model_elements_limit    model "elements = 200001"
key model_elements_exp      model "elements = 1e9"
key model_elements_typo     model "elements = 1OO"
key model_elements_overflow model "elements = 99999999999999999999999"
key model_modes_negative    model "modes_vertical = -1"
key model_modes_fraction    model "modes_vertical = 2.5"
key model_modes_huge        model "modes_horizontal = 201"
key model_modes_text        model "modes_torsional = x"
# keys of the removed identified reduced model (issue 13): refused naming the key and what replaced it
key model_id_amp_retired    model "identification_amplitude = 2" "identification_amplitude = 2: no longer a key"
key model_id_amp_replaced   model "identification_amplitude = 2" "model.residual_tolerance"
key model_id_twist_retired  model "identification_twist = 45" "identification_twist = 45: no longer a key"
key model_id_twist_replaced model "identification_twist = 45" "model.on_invalid"
key model_reduced_identified model "reduced = identified" "removed (issue 13); allowed: recomputed"
key model_reduced_other     model "reduced = polynomial" "allowed: recomputed"
key model_unknown_key       model "order = 2"
# ---- [simulation] ----
key sim_duration_zero       simulation "duration = 0"
key sim_duration_negative   simulation "duration = -1"
key sim_duration_huge       simulation "duration = 1e9"
key sim_step_negative       simulation "time_step = -1"
key sim_step_over_duration  simulation "time_step = 100"
key sim_probes_outside      simulation "probes = 0.5, 1.2"
key sim_probes_empty_item   simulation "probes = 0.5,,0.2"
key sim_probes_too_many     simulation "probes = .1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1" "probes"
key sim_probes_duplicate    simulation "probes = 0.5, 0.5" "repeats probe 1"
key sim_probes_same_digits  simulation "probes = 0.25, 0.2500000001" "repeats probe 1"
key sim_ramp_negative       simulation "wind_ramp = -1"
key sim_reverse_negative    simulation "wind_reverse_time = -1"
key sim_output_dt_huge      simulation "output_interval = 20"
# sizes computed from doubles (issue 14): bounded at scene load, never a cast overflow or GSL abort
key sim_output_dt_tiny      simulation "output_interval = 1e-300" "0.0001 <= output_interval"
key sim_output_dt_1e9       simulation "output_interval = 1e-9" "0.0001 <= output_interval"
key sim_step_tiny           simulation "time_step = 1e-12" "1e-06 <= time_step"
refused sim_samples_many "$tmp/base.ini" -1 "output_interval >= duration / 1000000" \
    --set simulation.duration=1000 --set simulation.output_interval=1e-4
refused sim_steps_many "$tmp/base.ini" -1 "time_step >= duration / 1000000000" \
    --set simulation.duration=1e5 --set simulation.time_step=1e-5
line=$(scene sim_duration_short simulation "output_interval = 0.5")
refused sim_duration_short "$tmp/sim_duration_short.ini" $((line + 1)) "duration = 10: too short to measure"
key sim_rho_inf_huge        simulation "rho_inf = 2"
key sim_tolerance_zero      simulation "tolerance = 0"
key sim_tolerance_retired   simulation "tolerance = 1e-6" "simulation.time_step"
key sim_unknown_key         simulation "integrator = euler"
# ---- [output] and the file's syntax ----
key output_dir_semicolon    output "directory = a;b" "directory"
key output_unknown_key      output "format = xml"
line=$(scene section_unknown spam "x = 1")
refused section_unknown "$tmp/section_unknown.ini" $((line - 1)) "[spam]"
line=$(scene syntax_bracket span "[span")
refused syntax_bracket "$tmp/syntax_bracket.ini" "$line" "span"
printf '[span]\nlength = 200\nlength = 300\nhorizontal_tension = 1\n[conductor]\nname = Drake\n' >"$tmp/dup.ini"
refused duplicate_key "$tmp/dup.ini" 3 "length"
printf '[span]\nhorizontal_tension = 25000\n[conductor]\nname = Drake\n' >"$tmp/nolength.ini"
refused missing_length "$tmp/nolength.ini" 0 "length"
# --set: the same checks, reported as "--set"
refused set_elements_negative "$tmp/base.ini" -1 "elements" --set model.elements=-1
refused set_id_twist_retired "$tmp/base.ini" -1 "identification_twist = 30: no longer a key" \
    --set model.identification_twist=30
refused set_id_amp_replaced "$tmp/base.ini" -1 "model.modes_vertical" --set model.identification_amplitude=1
refused set_probes_duplicate "$tmp/base.ini" -1 "repeats probe 1" --set simulation.probes=0.5,0.5
refused set_table_bad "$tmp/base.ini" -1 "aero_table" --set ice.aero_table="$tmp/base.ini"

# ---- [ice] aero_table: wrong tables (scene line 9 is aero_table) ----
src='# source: test_bad_input.sh'
table() { # NAME CONTENT-PRINTF-FORMAT WORD-IN-MESSAGE
    local name=$1 fmt=$2 word=$3
    printf "$fmt" >"$tmp/$name.csv"
    scene "tab_$name" ice "aero_table = $name.csv" >/dev/null
    refused "table_$name" "$tmp/tab_$name.ini" 8 "$word"
    grep -qF "$tmp/$name.csv" "$tmp/table_$name.err" && ok "table_$name: names the table" \
        || bad "table_$name: message lacks the table's path"
}
rows='0,1.2,0.1,0.01\n90,1.1,-0.3,0.02\n180,1.3,0.2,-0.01\n270,1.0,0.4,0.03\n'
table missing_column "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n-90,1.0,0.4\n0,1.2,0.1,0.01\n" "missing_column.csv:4"
table extra_column   "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01,7\n" "extra_column.csv:3"
table no_header      "$src\n-180,1.3,0.2,-0.01\n" "no_header.csv:2"
table no_source      "alpha_deg,cd,cl,cm\n$rows" "no_source.csv:1"
table not_periodic   "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n-90,1.0,0.4,0.03\n0,1.2,0.1,0.01\n90,1.1,-0.3,0.02\n180,1.5,0.2,-0.01\n" "not_periodic.csv:"
table unsorted       "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n0,1.2,0.1,0.01\n-90,1.0,0.4,0.03\n90,1.1,-0.3,0.02\n180,1.3,0.2,-0.01\n" "unsorted.csv:5"
table nan            "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n-90,nan,0.4,0.03\n0,1.2,0.1,0.01\n90,1.1,-0.3,0.02\n180,1.3,0.2,-0.01\n" "nan.csv:4"
table text           "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n-90,big,0.4,0.03\n" "text.csv:4"
table too_few_rows   "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n180,1.3,0.2,-0.01\n" "too_few_rows.csv"
table more_than_period "$src\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n0,1.2,0.1,0.01\n180,1.3,0.2,-0.01\n300,1,0,0\n" "more_than_period.csv:"
table spline_overshoot "$src\nalpha_deg,cd,cl,cm\n-180,1,0,0\n-90,1,0,0\n0,1,0,0\n0.001,2,0,0\n90,1,0,0\n" "spline_overshoot.csv:7: between these rows"
table spline_steep   "$src\nalpha_deg,cd,cl,cm\n-180,1,0,0\n-120,1,0,0\n-60,1,0,0\n0,1,0,0\n0.5,1,1,0\n60,1,1,0\n120,1,1,0\n" "periodic spline of cl"
table empty          "" "empty.csv"
table comments_only  "$src\n# nothing else\n" "comments_only.csv"
head -c 4096 /dev/urandom >"$tmp/junk.bin"; printf '\0\377\001' >>"$tmp/junk.bin"
cp "$tmp/junk.bin" "$tmp/junk_bin.csv"
scene tab_junk ice "aero_table = junk_bin.csv" >/dev/null
refused table_binary_junk "$tmp/tab_junk.ini" 8 "junk_bin.csv"
mkdir -p "$tmp/dir.csv"
scene tab_dir ice "aero_table = dir.csv" >/dev/null
refused table_directory "$tmp/tab_dir.ini" 8 "dir.csv"
# ---- unreadable scene files (tests run as root: a directory and a missing file) ----
mkdir -p "$tmp/adir.ini"
refused scene_directory "$tmp/adir.ini" 0 "adir.ini"
refused scene_missing "$tmp/nosuch.ini" 0 "nosuch.ini"
: >"$tmp/empty.ini"
refused scene_empty "$tmp/empty.ini" 0 "length"
head -c 2048 /dev/urandom >"$tmp/junk.ini"
refused scene_binary_junk "$tmp/junk.ini" 0 "junk.ini"

finish
