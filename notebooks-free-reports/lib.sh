# lib.sh: shell helpers shared by make_report.sh and plot_scene.sh (sourced, not run): read a
# number out of a summary.json with a real JSON parser (jq), pick CSV columns by name, format
# numbers. Needs: jq, awk (mawk or gawk), sed, grep; bash.

# jflat FILE: every scalar of a JSON file as "path<TAB>value" (jq: keys and array indices joined
# by ".", strings raw, numbers as written).
jflat() {
    [ -s "$1" ] && jq -r 'paths(scalars) as $p
        | "\($p | map(tostring) | join("."))\t\(getpath($p) | if type == "string" then . else tojson end)"' "$1"
}

# jfind FILE KEY [PREFER...]: the value of the first scalar whose path is KEY or ends with ".KEY";
# among several, the first whose path contains every PREFER word wins. Empty if none; "null" and
# empty strings count as none.
jfind() {
    local file=$1 key=$2; shift 2
    jflat "$file" | awk -F'\t' -v key="$key" -v prefs="$*" '
        BEGIN { np = split(prefs, pref, " ") }
        {
            p = $1; n = length(key)
            if (!(p == key || (length(p) > n && substr(p, length(p) - n) == "." key))) next
            if ($2 == "null" || $2 == "") next
            ok = 1
            for (i = 1; i <= np; i++) if (index(p, pref[i]) == 0) ok = 0
            if (ok && best == "") best = $2
            if (any == "") any = $2
        }
        END { print (best != "" ? best : any) }'
}

# csv_header FILE: the header line of a CSV (gallop's first line; comment lines of other CSVs skipped).
csv_header() { awk '!/^#/ && NF { print; exit }' "$1"; }

# csv_col FILE NAME: 1-based index of column NAME, empty if absent.
csv_col() {
    csv_header "$1" | awk -F, -v name="$2" '{ for (i = 1; i <= NF; i++) if ($i == name) { print i; exit } }'
}

# csv_find_col FILE REGEX: the name of the first column matching an awk regex, empty if none.
csv_find_col() {
    csv_header "$1" | awk -F, -v re="$2" '{ for (i = 1; i <= NF; i++) if ($i ~ re) { print $i; exit } }'
}

# csv_rows FILE: number of data rows.
csv_rows() { awk '/^#/ || !NF { next } h++ { n++ } END { print n + 0 }' "$1"; }

# csv_pick FILE NAME...: the named columns, whitespace-separated (CSV_PICK_SEP, e.g. a tab, for
# cells that hold spaces), without header or comments, for gnuplot; blank lines (gnuplot blocks)
# are kept. Fails (status 1, no output) if a column is missing.
csv_pick() {
    local file=$1; shift
    awk -F, -v names="$*" -v sep="${CSV_PICK_SEP:- }" '
        BEGIN { n = split(names, want, " ") }
        /^#/ { next }
        !hdr && NF {
            hdr = 1
            for (i = 1; i <= NF; i++) at[$i] = i
            for (k = 1; k <= n; k++) if (!(want[k] in at)) { bad = 1; exit 1 }
            next
        }
        !NF { if (hdr) print ""; next }
        {
            line = ""
            for (k = 1; k <= n; k++) line = line (k > 1 ? sep : "") $(at[want[k]])
            print line
        }
        END { if (bad || !hdr) exit 1 }' "$file"
}

# num FORMAT VALUE: printf a number, "n/a" if the value is empty, null or not a number.
num() {
    case $2 in
        ''|null|nan|NaN|-nan|inf|-inf) printf 'n/a' ;;
        *[!0-9eE.+-]*) printf '%s' "$2" ;;
        *) LC_ALL=C printf "$1" "$2" 2>/dev/null || printf '%s' "$2" ;;
    esac
}

# has_rows FILE: the file exists and has at least one data row.
has_rows() { [ -s "$1" ] && [ "$(csv_rows "$1")" -gt 0 ]; }

# jget FILE KEY...: the value of the last key, each key found on a line after the one before it (no jq:
# a line-based scan of gallop's own indented summary.json, for the bundle report scripts)
jget() {
    local f=$1; shift
    [ -r "$f" ] || return 0
    awk -v keys="$*" 'BEGIN { n = split(keys, k, " "); i = 1 }
        i <= n && index($0, "\"" k[i] "\"") { if (i == n) { v = $0; sub(/^[^:]*:[[:space:]]*/, "", v); sub(/,$/, "", v); print v; exit } i++ }' "$f"
}
