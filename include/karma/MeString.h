/* MeString.h -- the C string and formatting headers Karma's programs expect from one include
 * (snprintf and vsnprintf are standard C99 here). */
#ifndef ME_STRING_H
#define ME_STRING_H

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#endif /* ME_STRING_H */
