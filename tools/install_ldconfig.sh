#!/bin/sh
# install_ldconfig.sh LIBDIR -- run by `make install` after `cmake --install`: make libkarma.so
# findable by the dynamic loader, or say exactly what the user must do.
#
#  - staged install (DESTDIR set): nothing; the package's own scripts run ldconfig;
#  - LIBDIR is a directory the loader searches (e.g. /usr/local/lib on Debian) and we are root:
#    run ldconfig, so a program linked with -lkarma starts at once;
#  - the same but not root: print the `sudo ldconfig` line;
#  - LIBDIR is not searched (a custom prefix): print the rpath line (README, "Installing elsewhere").
#
# Environment (tests use them): LDCONFIG, the ldconfig command (default: ldconfig, then /sbin/ldconfig);
# KARMA_INSTALL_UID, the user id to act as (default: id -u).
libdir=${1:?usage: install_ldconfig.sh LIBDIR}
if [ -n "${DESTDIR:-}" ]; then
    echo "karma: staged into DESTDIR=$DESTDIR; ldconfig is left to the package's scripts"
    exit 0
fi
ldconfig=${LDCONFIG:-}
if [ -z "$ldconfig" ]; then
    for c in ldconfig /sbin/ldconfig /usr/sbin/ldconfig; do
        if command -v "$c" >/dev/null 2>&1; then ldconfig=$c; break; fi
    done
fi
uid=${KARMA_INSTALL_UID:-$(id -u)}
searched=no
if [ -n "$ldconfig" ]; then
    # -v -N -X: list the directories the loader's cache is built from, changing nothing.
    if "$ldconfig" -v -N -X 2>/dev/null | sed -n 's/^\(\/[^:]*\):.*/\1/p' | grep -qx "$libdir"; then
        searched=yes
    fi
fi
if [ "$searched" = yes ]; then
    if [ "$uid" = 0 ]; then
        "$ldconfig" && echo "karma: ran ldconfig: programs linked with -lkarma find $libdir/libkarma.so"
    else
        echo "karma: $libdir is in the loader's path; run 'sudo ldconfig' once so programs find libkarma.so"
    fi
else
    echo "karma: $libdir is not in the loader's path: link programs with -Wl,-rpath,$libdir"
    echo "       and let pkg-config find karma.pc with: export PKG_CONFIG_PATH=$libdir/pkgconfig"
fi
