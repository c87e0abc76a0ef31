/* Fixture of tests/cmake/layers.cmake (never compiled): an Mcd file that includes Mdt. */
#include "../mdt/body.h"
