/* MeCall.h -- calling-convention and export macros of Karma's headers.
 *
 * Karma's declarations and callbacks are written `void MEAPI f(...)`, programs' entry points
 * `int MEAPI_CDECL main(...)`. This library uses the compiler's default convention everywhere, so
 * the convention macros are empty (a callback declared MEAPI matches the library's pointer types
 * on every platform); MEPUBLIC marks an exported declaration, as ME_API does. */
#ifndef ME_CALL_H
#define ME_CALL_H

#include <karma/config.h>

#define MEAPI
#define MEAPI_CDECL
#define MEAPI_STDCALL
#define MEAPI_FASTCALL

#define MEPUBLIC ME_API

#endif /* ME_CALL_H */
