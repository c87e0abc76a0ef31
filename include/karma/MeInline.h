/* MeInline.h -- Karma's inlining macros: MeINLINE marks a function defined in a header, and MeDEFINE
 * is 1 when such definitions are compiled in (always, here: every compiler this library supports
 * inlines). */
#ifndef ME_INLINE_H
#define ME_INLINE_H

#define MeDEFINE 1
#define MeINLINE static inline

#endif /* ME_INLINE_H */
