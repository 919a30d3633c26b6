#!/usr/bin/env bash
# test_header.sh: the public headers. include/gallop.h includes every header under
# include/gallop/ (a new header cannot be forgotten); every header has extern "C" guards and
# compiles on its own; a file that includes only gallop.h compiles as C (-std=c11 -Wall -Wextra
# -pedantic -Werror) and as C++ (g++ -fsyntax-only). Only include/ and the system's include
# directories are on the path (the Makefile's CPPFLAGS without -Isrc): no public header may need
# a private one.
set -u
. "$(dirname "$0")/lib.sh"
scratch header

CC=${CC:-cc}
CXX=${CXX:-g++}
flags=()
for f in ${GALLOP_CPPFLAGS:--Iinclude -Isrc -I/usr/include/suitesparse -D_POSIX_C_SOURCE=200809L}; do
    [ "$f" = "-Isrc" ] || flags+=("$f")
done

headers=$(cd include && find gallop -name '*.h' | sort)
[ -n "$headers" ] && ok "$(echo "$headers" | wc -l) public headers" || bad "no headers under include/gallop"

# every header is included by gallop.h
missing=""
for h in $headers; do
    grep -qE "^#include \"$h\"" include/gallop.h || missing="$missing $h"
done
[ -z "$missing" ] && ok "gallop.h includes every header under include/gallop/" \
    || bad "gallop.h lacks:$missing"
# and includes nothing that does not exist
stale=""
for h in $(sed -n 's/^#include "\(gallop\/[^"]*\)".*/\1/p' include/gallop.h); do
    [ -f "include/$h" ] || stale="$stale $h"
done
[ -z "$stale" ] && ok "every header gallop.h includes exists" || bad "gallop.h includes missing files:$stale"

# extern "C" guards, and each header compiles on its own (it includes what it uses)
noguard=""; alone=""
for h in $headers; do
    if ! grep -q '^#ifdef __cplusplus' "include/$h" || ! grep -q '^extern "C" {' "include/$h"; then
        noguard="$noguard $h"
    fi
    printf '#include "%s"\n#include "%s"\nint gallop_header_test;\n' "$h" "$h" >"$tmp/one.c"
    "$CC" -std=c11 -Wall -Wextra -pedantic -Werror "${flags[@]}" -fsyntax-only "$tmp/one.c" \
        >"$tmp/one.err" 2>&1 || alone="$alone $h($(head -n 1 "$tmp/one.err"))"
done
[ -z "$noguard" ] && ok "every header has extern \"C\" guards" || bad "no extern \"C\" guards:$noguard"
[ -z "$alone" ] && ok "every header compiles on its own, twice included" \
    || bad "headers that do not compile alone:$alone"

# gallop.h alone, as C and as C++
printf '#include "gallop.h"\nint main(void) { return gal_exit_code(GAL_OK); }\n' >"$tmp/all.c"
if "$CC" -std=c11 -Wall -Wextra -pedantic -Werror "${flags[@]}" -c "$tmp/all.c" -o "$tmp/all.o" \
    2>"$tmp/c.err"; then
    ok "gallop.h compiles as C11 (-Wall -Wextra -pedantic -Werror)"
else
    bad "gallop.h as C: $(head -n 3 "$tmp/c.err")"
fi
# as C++: compiled to an object, whose references to the library must be C names (unmangled)
printf '#include "gallop.h"\nint main() { gal_scene sc; return gal_exit_code(gal_scene_load(&sc, "x", 0, 0, 0)); }\n' \
    >"$tmp/all.cpp"
if ! command -v "$CXX" >/dev/null; then
    bad "no C++ compiler ($CXX) to check the extern \"C\" guards"
elif ! "$CXX" -Wall -Wextra -pedantic -Werror "${flags[@]}" -c "$tmp/all.cpp" -o "$tmp/cxx.o" \
    2>"$tmp/cxx.err"; then
    bad "gallop.h as C++: $(head -n 3 "$tmp/cxx.err")"
elif ! nm "$tmp/cxx.o" | grep -qE ' U gal_scene_load$' || ! nm "$tmp/cxx.o" | grep -qE ' U gal_exit_code$'; then
    bad "gallop.h as C++: the library's functions get C++ (mangled) names: $(nm "$tmp/cxx.o" | grep ' U ' | head -n 3)"
else
    ok "gallop.h compiles as C++ ($CXX -pedantic -Werror), with C linkage"
fi

finish
