/* Fixture of tests/cmake/layers.cmake (never compiled): a Kea file that includes Mdt. */
#include "../world.h"
#include <karma/MdtBody.h>
#include "kea_internal.h"
