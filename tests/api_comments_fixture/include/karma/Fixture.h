/* Fixture.h -- read (never compiled) by the docs_api_comments_catches_missing test:
 * tests/scripts/check_api_comments.sh must name Undocumented, SharedSecond, PlainCommented and
 * InlineUndocumented, and none of the documented ones. */

/** Documented: its own comment. */
ME_API void Documented(int a);
ME_API void Undocumented(int a);
/** A comment over a run documents its first declaration only. */
ME_API void SharedFirst(void);
ME_API void SharedSecond(void);
/* A plain comment documents nothing. */
ME_API void PlainCommented(void);
ME_API int Trailing(void); /**< A trailing comment documents its declaration. */
/** Documented over two lines, for a declaration
 *  that wraps. */
ME_API void Wrapped(int a,
                    int b);
/** A public inline function, documented. */
static inline int InlineDocumented(int i) { return i; }
static inline int InlineUndocumented(int i) { return i; }
