/* Fixture of tests/cmake/layers.cmake (never compiled): an Mdt stage that includes Mcd and the
 * contact struct. */
#include <karma/McdModel.h>
#include "bcl/contact_internal.h"
