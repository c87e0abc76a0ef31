/* MeSimpleFile.h -- plain file access by integer handle, and a search through Karma's resource
 * directories.
 *
 * Handles are POSIX file descriptors (-1 on failure). MeOpenWithSearch tries the name as given, then
 * under each directory of MeGetDefaultFileLocation(0, 1, ...): "Resources/", "../Resources/" and so on
 * up the tree, as Karma's demos laid out their data. */
#ifndef ME_SIMPLE_FILE_H
#define ME_SIMPLE_FILE_H

#include <stdarg.h>
#include <stdio.h>

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** How to open a file. */
typedef enum {
    kMeOpenModeRDONLY,  /**< read only */
    kMeOpenModeWRONLY,  /**< write: created, or truncated when it exists */
    kMeOpenModeRDWR,    /**< read and write an existing file */
    kMeOpenModeRDBINARY /**< read only, binary (the same as RDONLY on POSIX) */
} MeOpenMode_enum;

/** Where MeLseek's offset counts from. */
typedef enum {
    kMeSeekSET, /**< the start of the file */
    kMeSeekCUR, /**< the current position */
    kMeSeekEND  /**< the end of the file */
} MeSeekOrigin_enum;

/** Open filename exactly as given; a handle, or -1. */
ME_API int MEAPI MeOpenRaw(const char *filename, MeOpenMode_enum mode);
/** Open filename (relative names from the current directory); a handle, or -1. */
ME_API int MEAPI MeOpen(const char *filename, MeOpenMode_enum mode);
/** Open filename, trying each default location in turn; a handle, or -1. */
ME_API int MEAPI MeOpenWithSearch(const char *filename, MeOpenMode_enum mode);
/** Move the file position; the new position from the start, or -1. */
ME_API int MEAPI MeLseek(int file, int offset, MeSeekOrigin_enum origin);
/** Read up to count bytes; the number read (0 at the end), or -1. */
ME_API int MEAPI MeRead(int file, void *buf, int count);
/** Write count bytes; the number written, or -1. */
ME_API int MEAPI MeWrite(int file, void *buf, int count);
/** Close the handle; 0, or -1. */
ME_API int MEAPI MeClose(int file);
/** The i-th search directory (with its trailing '/'; "" is the current directory), or NULL past the
 *  last. */
ME_API const char *MEAPI MeGetDefaultFileLocation(int i);
/** The rest of the file from the current position, in a block from MeMemoryAPI.create (free it
 *  with MeMemoryAPI.destroy) with a '\0' after the data; *size = its length. NULL on failure. */
ME_API char *MEAPI MeLoadWholeFileHandle(const int f, int *size);
/** Write size bytes of data to the file. */
ME_API void MEAPI MeSaveWholeFileHandle(const int f, const char *data, const int size);

ME_EXTERN_C_END

#endif /* ME_SIMPLE_FILE_H */
