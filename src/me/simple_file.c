/* simple_file.c -- MeSimpleFile: POSIX file descriptors and the resource search path. */
#if !defined(_WIN32)
#  define _POSIX_C_SOURCE 200809L
#endif

#include <stdio.h>
#include <string.h>

#if defined(_WIN32)
#  include <fcntl.h>
#  include <io.h>
#  define ME_OPEN_ _open
#  define ME_READ_ _read
#  define ME_WRITE_ _write
#  define ME_LSEEK_ _lseek
#  define ME_CLOSE_ _close
#  define ME_BINARY_ _O_BINARY
#else
#  include <fcntl.h>
#  include <unistd.h>
#  define ME_OPEN_ open
#  define ME_READ_ read
#  define ME_WRITE_ write
#  define ME_LSEEK_ lseek
#  define ME_CLOSE_ close
#  define ME_BINARY_ 0
#endif

#include <karma/MeMemory.h>
#include <karma/MeSimpleFile.h>

/* The current directory, then the Resources directories of Karma's SDK layout seen from a demo's
 * working directory at various depths (directories and their ka_files subdirectories). */
static const char *const defaultLocations[] = {
    "",
    "Resources/",
    "../Resources/",
    "../../Resources/",
    "../../../Resources/",
    "../../../../Resources/",
    "../bin/Resources/",
    "../../bin/Resources/",
    "../../../bin/Resources/",
    "../../../../bin/Resources/",
    "../../../../demos/Resources/",
    "Resources/ka_files/",
    "../Resources/ka_files/",
    "../../Resources/ka_files/",
    "../../../Resources/ka_files/",
    "../../../../Resources/ka_files/",
    NULL,
};
enum { LOCATION_COUNT = sizeof defaultLocations / sizeof defaultLocations[0] - 1 };

int MEAPI MeOpenRaw(const char *filename, MeOpenMode_enum mode)
{
    int flags;
    if (!filename)
        return -1;
    switch (mode) {
    case kMeOpenModeRDONLY: flags = O_RDONLY; break;
    case kMeOpenModeWRONLY: flags = O_WRONLY | O_CREAT | O_TRUNC; break;
    case kMeOpenModeRDWR: flags = O_RDWR; break;
    case kMeOpenModeRDBINARY: flags = O_RDONLY | ME_BINARY_; break;
    default: return -1;
    }
    return ME_OPEN_(filename, flags | ME_BINARY_, 0666);
}

int MEAPI MeOpen(const char *filename, MeOpenMode_enum mode) { return MeOpenRaw(filename, mode); }

int MEAPI MeOpenWithSearch(const char *filename, MeOpenMode_enum mode)
{
    char path[FILENAME_MAX];
    int i;
    if (!filename)
        return -1;
    for (i = 0; defaultLocations[i]; i++) {
        int f;
        size_t prefix = strlen(defaultLocations[i]);
        if (prefix + strlen(filename) + 1 > sizeof path)
            continue;
        memcpy(path, defaultLocations[i], prefix);
        strcpy(path + prefix, filename);
        f = MeOpenRaw(path, mode);
        if (f >= 0)
            return f;
    }
    return -1;
}

int MEAPI MeLseek(int file, int offset, MeSeekOrigin_enum origin)
{
    int whence = origin == kMeSeekCUR ? SEEK_CUR : origin == kMeSeekEND ? SEEK_END : SEEK_SET;
    return (int)ME_LSEEK_(file, offset, whence);
}

int MEAPI MeRead(int file, void *buf, int count)
{
    return count < 0 ? -1 : (int)ME_READ_(file, buf, (size_t)count);
}

int MEAPI MeWrite(int file, void *buf, int count)
{
    return count < 0 ? -1 : (int)ME_WRITE_(file, buf, (size_t)count);
}

int MEAPI MeClose(int file) { return ME_CLOSE_(file); }

const char *MEAPI MeGetDefaultFileLocation(int i)
{
    return (i >= 0 && i < LOCATION_COUNT) ? defaultLocations[i] : NULL;
}

char *MEAPI MeLoadWholeFileHandle(const int f, int *size)
{
    /* The size is not asked of the file (it may be a pipe): read in doubling blocks. */
    size_t capacity = 4096, used = 0;
    char *data = MeMemoryAPI.create(capacity);
    if (size)
        *size = 0;
    if (!data)
        return NULL;
    for (;;) {
        int got;
        if (used + 1 == capacity) {
            char *grown = MeMemoryAPI.resize(data, capacity * 2);
            if (!grown) {
                MeMemoryAPI.destroy(data);
                return NULL;
            }
            data = grown;
            capacity *= 2;
        }
        got = MeRead(f, data + used, (int)(capacity - 1 - used));
        if (got < 0) {
            MeMemoryAPI.destroy(data);
            return NULL;
        }
        if (got == 0)
            break;
        used += (size_t)got;
    }
    data[used] = '\0';
    if (size)
        *size = (int)used;
    return data;
}

void MEAPI MeSaveWholeFileHandle(const int f, const char *data, const int size)
{
    int done = 0;
    while (data && done < size) {
        int wrote = MeWrite(f, (void *)(data + done), size - done);
        if (wrote <= 0)
            return;
        done += wrote;
    }
}
