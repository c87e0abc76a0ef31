KARMA=$HOME/src/karma                  # your clone of this repository
PREFIX=$HOME/karma                     # any directory you can write to
make -C $KARMA install PREFIX=$PREFIX
export PKG_CONFIG_PATH=$PREFIX/lib/pkgconfig
cc hello.c $(pkg-config --cflags --libs karma) -Wl,-rpath,$PREFIX/lib -o hello
./hello
cmake -S . -B build -DCMAKE_PREFIX_PATH=$PREFIX    # with the CMakeLists.txt below next to hello.c
cmake --build build
build/hello
