# json_flat.awk: flattens a JSON file into one "path<TAB>value" line per scalar, e.g.
#   sag_m	4.21
#   modes.0.family	vertical
#   full.frequency_hz	0.52
# Object members are joined with ".", array elements are numbered from 0. Strings lose their
# quotes (escapes other than \" and \\ are left as they are). Layout-independent: the whole file
# is read and tokenized, so it does not rely on one key per line. No jq needed.
BEGIN { RS = "^$" }   # slurp the file (gawk/mawk: a regex RS that never matches)
{ text = text $0 }
END {
    depth = 0; key = ""; s = text
    while (length(s) > 0) {
        if (match(s, /^[ \t\r\n,:]+/)) { s = substr(s, RLENGTH + 1); continue }
        c = substr(s, 1, 1)
        if (c == "{" || c == "[") {
            push(c); s = substr(s, 2); continue
        }
        if (c == "}" || c == "]") {
            depth--; s = substr(s, 2); after_value(); continue
        }
        if (c == "\"") {
            # a string: find the closing quote that is not escaped
            i = 2; v = ""
            while (i <= length(s)) {
                ch = substr(s, i, 1)
                if (ch == "\\") { v = v substr(s, i + 1, 1); i += 2; continue }
                if (ch == "\"") break
                v = v ch; i++
            }
            s = substr(s, i + 1)
            # a key if a colon follows (inside an object, expecting a key)
            if (depth > 0 && type[depth] == "{" && !have_key[depth]) {
                name[depth] = v; have_key[depth] = 1; continue
            }
            emit(v); continue
        }
        if (match(s, /^[^ \t\r\n,:{}\[\]]+/)) {
            v = substr(s, 1, RLENGTH); s = substr(s, RLENGTH + 1); emit(v); continue
        }
        s = substr(s, 2)   # anything else: skip it
    }
}
function path(   p, d) {
    p = ""
    for (d = 1; d <= depth; d++) p = p (p == "" ? "" : ".") name[d]
    return p
}
function push(c) {
    depth++; type[depth] = c; have_key[depth] = 0
    if (c == "[") { idx[depth] = 0; name[depth] = 0 }
}
function after_value() {
    if (depth < 1) return
    if (type[depth] == "{") have_key[depth] = 0
    else { idx[depth]++; name[depth] = idx[depth] }
}
function emit(v) {
    print path() "\t" v
    after_value()
}
