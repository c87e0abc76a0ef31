/* Fixture of tests/cmake/layers.cmake (never compiled): an Mdt file that includes Mcd. */
#include <karma/McdModel.h>
