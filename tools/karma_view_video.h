/* karma_view_video.h -- `karma render --mp4`: frames piped to the ffmpeg program, which encodes
 * them as H.264 in an MP4 file (Debian's ffmpeg package). */
#ifndef KARMA_TOOL_VIEW_VIDEO_H
#define KARMA_TOOL_VIEW_VIDEO_H

#include <stdio.h>

typedef struct KarmaVideo {
    FILE *pipe;        /**< ffmpeg's standard input */
    long pid;          /**< ffmpeg's process */
    int width, height;
    unsigned char *rgba; /**< one frame */
} KarmaVideo;

/** Start ffmpeg writing `path`: width × height pixels, `fps` frames a second. Returns 0, or −1
 *  after saying why on stderr (ffmpeg cannot be run, out of memory). */
int KarmaVideoOpen(KarmaVideo *v, const char *path, int width, int height, int fps);
/** Append one RGBA frame (top row first). Returns 0, or −1 when ffmpeg stopped taking frames. */
int KarmaVideoWrite(KarmaVideo *v, const unsigned char *rgba);
/** Finish the file and wait for ffmpeg. Returns 0 when ffmpeg wrote it, −1 (said on stderr) otherwise. */
int KarmaVideoClose(KarmaVideo *v);

#endif /* KARMA_TOOL_VIEW_VIDEO_H */
