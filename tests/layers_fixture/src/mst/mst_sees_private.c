/* Fixture of tests/cmake/layers.cmake (never compiled): an Mst file that reaches past the public
 * headers into Mcd's and Mdt's private ones; its public and Me includes are allowed. */
#include <karma/McdModel.h>
#include <string.h>

#include "../mcd/framework.h"
#include "../mdt/bcl/contact_internal.h"
#include "../me/check.h"
#include "bridge.h"
