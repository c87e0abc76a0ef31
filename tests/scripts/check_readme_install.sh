#!/usr/bin/env bash
# check_readme_install.sh SOURCE BUILD WORK CC SANITIZE -- the README's install lines work as written.
#
# 1. Custom prefix: examples/install/custom_prefix.sh (the README shows it exactly, docs_listings) runs
#    verbatim in a fresh directory holding hello.c and examples/install/CMakeLists.txt, with HOME in
#    scratch, no LD_LIBRARY_PATH, its `make` being this tree's Makefile on the already built BUILD and
#    its `cc` the build's compiler (with the sanitizers in an ASan build). Both programs must print the
#    fall; the pkg-config one must carry the rpath and load libkarma.so from the prefix, and without the
#    rpath (when no libkarma.so is in the loader's cache) it must fail to start: the rpath is what works.
# 2. Default prefix: `make install` staged with DESTDIR writes a karma.pc for /usr/local and does not run
#    ldconfig; /usr/local/lib is a directory the loader searches; tools/install_ldconfig.sh runs ldconfig
#    as root when the directory is searched, and prints the right line otherwise (with a stand-in ldconfig).
set -eu   # no pipefail: `grep -q` may close a pipe early
source=$1 build=$2 work=$3 compiler=$4 sanitize=$5
fail() { echo "FAIL: $*" >&2; exit 1; }
expected='Karma [0-9.]+ \((single|double) precision\): the ball fell from 10 m to 5\.013 m in one second'
rm -rf "$work"
mkdir -p "$work/home/src" "$work/bin" "$work/app"
ln -s "$source" "$work/home/src/karma"
flags=""
[ "$sanitize" = ON ] && flags="-fsanitize=address,undefined -fno-sanitize-recover=all"
cat > "$work/bin/make" <<WRAP
#!/bin/sh
# this tree's Makefile, on the build the test suite already made (-o build: do not rebuild it)
exec $(command -v make) -o build BUILD="$build" "\$@"
WRAP
cat > "$work/bin/cc" <<WRAP
#!/bin/sh
exec "$compiler" $flags "\$@"
WRAP
chmod +x "$work/bin/make" "$work/bin/cc"
cp "$source/examples/hello.c" "$source/examples/install/CMakeLists.txt" "$work/app/"

# ---- 1. custom prefix ----------------------------------------------------------------------------
cd "$work/app"
out=$(env -u LD_LIBRARY_PATH -u PKG_CONFIG_PATH -u CMAKE_PREFIX_PATH HOME="$work/home" \
      PATH="$work/bin:$PATH" CC="$work/bin/cc" sh -e "$source/examples/install/custom_prefix.sh" 2>&1) \
    || { echo "$out"; fail "examples/install/custom_prefix.sh failed"; }
echo "$out" | grep -q "is not in the loader's path: link programs with -Wl,-rpath,$work/home/karma/lib" \
    || { echo "$out"; fail "make install did not print the rpath line for a custom prefix"; }
n=$(echo "$out" | grep -Ec "$expected" || true)
[ "$n" = 2 ] || { echo "$out"; fail "expected both programs (pkg-config, CMake) to print the fall, got $n"; }
readelf -d hello | grep -E 'R(UN)?PATH' | grep -qF "$work/home/karma/lib" || fail "hello carries no rpath to the prefix"
env -u LD_LIBRARY_PATH ldd hello | grep -qE "libkarma\.so.* => $work/home/karma/lib/libkarma\.so" \
    || fail "hello does not load libkarma.so from the prefix: $(ldd hello | grep karma)"
if ! /sbin/ldconfig -p 2>/dev/null | grep -q 'libkarma\.so'; then
    PKG_CONFIG_PATH="$work/home/karma/lib/pkgconfig" "$work/bin/cc" hello.c \
        $(PKG_CONFIG_PATH="$work/home/karma/lib/pkgconfig" pkg-config --cflags --libs karma) -o hello_no_rpath
    if env -u LD_LIBRARY_PATH ./hello_no_rpath >/dev/null 2>&1; then
        fail "a program built without the rpath started: the rpath line proves nothing here"
    fi
    echo "without the rpath the program does not start; with it, it does"
fi
echo "custom prefix: both programs built and ran from the README's lines"

# ---- 2. default prefix -----------------------------------------------------------------------------
out=$(PATH="$work/bin:$PATH" make -C "$source" install DESTDIR="$work/stage" 2>&1) || { echo "$out"; fail "staged make install"; }
echo "$out" | grep -q "staged into DESTDIR" || { echo "$out"; fail "a staged install must leave ldconfig alone"; }
pc="$work/stage/usr/local/lib/pkgconfig/karma.pc"
grep -qx 'prefix=/usr/local' "$pc" || fail "karma.pc for the default prefix: $(head -2 "$pc")"
grep -q '^Libs:.* -lm' "$pc" || fail "karma.pc's Libs lack -lm"
[ -e "$work/stage/usr/local/lib/libkarma.so" ] || fail "libkarma.so not in /usr/local/lib"
if [ -x /sbin/ldconfig ]; then
    /sbin/ldconfig -v -N -X 2>/dev/null | grep -q '^/usr/local/lib:' \
        || fail "/usr/local/lib is not in the loader's path here: the README's default-prefix claim is false"
fi
cat > "$work/bin/fake_ldconfig" <<'FAKE'
#!/bin/sh
# lists one searched directory; a run without options is recorded
if [ "$#" -gt 0 ]; then echo "$FAKE_SEARCHED: (from fake.conf:1)"; else touch "$FAKE_RAN"; fi
FAKE
chmod +x "$work/bin/fake_ldconfig"
decide() { # uid dir -> output
    env -u DESTDIR LDCONFIG="$work/bin/fake_ldconfig" FAKE_SEARCHED=/opt/searched FAKE_RAN="$work/ran" \
        KARMA_INSTALL_UID=$1 sh "$source/tools/install_ldconfig.sh" "$2"
}
rm -f "$work/ran"; o=$(decide 0 /opt/searched)
[ -e "$work/ran" ] && echo "$o" | grep -q "ran ldconfig" || fail "root, searched directory: ldconfig not run ($o)"
rm -f "$work/ran"; o=$(decide 1000 /opt/searched)
[ ! -e "$work/ran" ] && echo "$o" | grep -q "sudo ldconfig" || fail "user, searched directory: ($o)"
rm -f "$work/ran"; o=$(decide 0 /opt/elsewhere/lib)
[ ! -e "$work/ran" ] && echo "$o" | grep -q -- "-Wl,-rpath,/opt/elsewhere/lib" || fail "root, other directory: ($o)"
echo "default prefix: staged install for /usr/local, ldconfig decided as documented"
