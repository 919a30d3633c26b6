#!/usr/bin/env bash
# test_install.sh: `make install PREFIX=$(mktemp -d)` installs the binary, libgallop.a, the
# headers, the man page, data/ and gallop.pc; the installed gallop finds its data without
# GALLOP_DATA (a scene naming a conductor, run from another directory); the installed pkg-config
# builds the README's example (examples/first_frequencies.c), which agrees with `gallop modes`.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
root=$PWD
scratch install
prefix=$tmp/prefix

unset MAKEFLAGS MFLAGS MAKELEVEL
if make -C "$root" -j2 install PREFIX="$prefix" > "$tmp/install.log" 2>&1; then
  ok "make install PREFIX=$prefix"
else
  bad "make install: $(tail -5 "$tmp/install.log")"; echo "#summary $pass $fail"; exit 1
fi
for f in bin/gallop lib/libgallop.a include/gallop.h include/gallop/base/error.h include/gallop/run/sim.h \
         share/man/man1/gallop.1 share/gallop/conductors.csv share/gallop/scenes/drake_300m.ini \
         lib/pkgconfig/gallop.pc; do
  [ -s "$prefix/$f" ] || bad "not installed: $f"
done
ok "installed: binary, library, headers, man page, data, gallop.pc"
n=$(cd "$root/include" && find gallop -name '*.h' | wc -l); m=$(cd "$prefix/include" && find gallop -name '*.h' | wc -l)
[ "$n" -eq "$m" ] && ok "every header installed ($n)" || bad "$m of $n headers installed"

# the installed gallop finds conductors.csv without GALLOP_DATA: a scene naming Drake, elsewhere
mkdir -p "$tmp/elsewhere/scenes"
cp "$root/data/scenes/drake_300m.ini" "$tmp/elsewhere/scenes/"
if (cd "$tmp/elsewhere" && env -u GALLOP_DATA "$prefix/bin/gallop" modes scenes/drake_300m.ini -o out > log 2>&1); then
  ok "installed gallop runs a scene outside the source tree without GALLOP_DATA"
else
  bad "installed gallop: $(tail -2 "$tmp/elsewhere/log")"
fi
"$prefix/bin/gallop" --version > /dev/null && ok "installed gallop --version" || bad "installed gallop --version"

# the example through the installed pkg-config
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
if pkg-config --exists gallop && cc -std=c11 -Wall -Wextra -Werror "$root/examples/first_frequencies.c" \
     $(pkg-config --cflags --libs gallop) -o "$tmp/ff" 2> "$tmp/cc.err"; then
  ok "the example builds with pkg-config --cflags --libs gallop ($(pkg-config --modversion gallop))"
else
  bad "the example does not build: $(head -3 "$tmp/cc.err")"
fi
if [ -x "$tmp/ff" ] && (cd "$tmp/elsewhere" && env -u GALLOP_DATA "$tmp/ff" scenes/drake_300m.ini > ff.out 2>&1); then
  f1=$(awk '$1 == "horizontal" { print $2; exit }' "$tmp/elsewhere/ff.out")
  f2=$(awk -F, '$2 == "horizontal" { print $4; exit }' "$tmp/elsewhere/out/modes.csv")
  awk -v a="$f1" -v b="$f2" 'BEGIN { d = a - b; exit !(a > 0 && (d < 0 ? -d : d) < 1e-6 * b) }' \
    && ok "installed example: first horizontal $f1 Hz = gallop modes $f2 Hz" \
    || bad "installed example: $f1 Hz, gallop modes $f2 Hz"
else
  bad "installed example failed: $(cat "$tmp/elsewhere/ff.out" 2>/dev/null)"
fi
finish
