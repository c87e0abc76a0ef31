/* karma_view_video.c -- frames to an MP4 file through the ffmpeg program, started with fork and
 * exec (no shell: the file name is passed as it is) and fed raw RGBA frames on a pipe. */
#define _POSIX_C_SOURCE 200809L /* fork, pipe, fdopen, waitpid */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "karma_view_video.h"

/** Exit status of the child when ffmpeg cannot be run (as a shell says "not found"). */
#define KARMA_VIDEO_NO_FFMPEG 127

int KarmaVideoOpen(KarmaVideo *v, const char *path, int width, int height, int fps)
{
    memset(v, 0, sizeof *v);
    v->width = width, v->height = height;
    v->rgba = malloc((size_t)width * (size_t)height * 4);
    int fds[2];
    if (!v->rgba || pipe(fds) != 0) {
        fprintf(stderr, "karma: cannot start the video (out of memory or pipes)\n");
        free(v->rgba);
        return -1;
    }
    char size[32], rate[16];
    snprintf(size, sizeof size, "%dx%d", width, height);
    snprintf(rate, sizeof rate, "%d", fps);
    /* H.264 in yuv420p needs even sizes: an odd one is padded by a pixel. */
    char *const args[] = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgba",
                          "-s", size, "-r", rate, "-i", "-", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
                          "-pix_fmt", "yuv420p", "-movflags", "+faststart", (char *)path, NULL};
    fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "karma: cannot start ffmpeg\n");
        close(fds[0]), close(fds[1]), free(v->rgba);
        return -1;
    }
    if (pid == 0) {
        dup2(fds[0], STDIN_FILENO);
        close(fds[0]), close(fds[1]);
        execvp("ffmpeg", args);
        _exit(KARMA_VIDEO_NO_FFMPEG);
    }
    close(fds[0]);
    v->pid = pid;
    v->pipe = fdopen(fds[1], "wb");
    signal(SIGPIPE, SIG_IGN); /* a failed ffmpeg shows as a failed write, not a killed karma */
    return v->pipe ? 0 : -1;
}

int KarmaVideoWrite(KarmaVideo *v, const unsigned char *rgba)
{
    size_t bytes = (size_t)v->width * (size_t)v->height * 4;
    return v->pipe && fwrite(rgba, 1, bytes, v->pipe) == bytes ? 0 : -1;
}

int KarmaVideoClose(KarmaVideo *v)
{
    if (v->pipe)
        fclose(v->pipe);
    int status = 0;
    int waited = v->pid > 0 && waitpid((pid_t)v->pid, &status, 0) == (pid_t)v->pid;
    free(v->rgba);
    memset(v, 0, sizeof *v);
    if (waited && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return 0;
    if (waited && WIFEXITED(status) && WEXITSTATUS(status) == KARMA_VIDEO_NO_FFMPEG)
        fprintf(stderr, "karma: ffmpeg not found: install it (Debian package ffmpeg) to write videos\n");
    else
        fprintf(stderr, "karma: ffmpeg failed to write the video\n");
    return -1;
}
