/* window_under_xvfb.c -- a real window (GLFW on an X display; CTest runs this under Xvfb): it opens
 * with Karma's title option, RRun runs its frames (-timeout) calling the tick each frame, the picture
 * shown holds a red box at the look-at point on the default black background, and it closes.
 * Exit status 0 on success, 1 with a message. Not a cmocka test: it needs the display. */
#include <stdio.h>
#include <stdlib.h>

#include <MeViewer.h>

static int ticks;
static void MEAPI tick(RRender *rc, void *userdata)
{
    ticks++;
}

int main(int argc, char **argv)
{
    const char *args[] = {"window", "-gl", "-size", "200x150", "-timeout", "12"};
    MeCommandLineOptions *o = MeCommandLineOptionsCreate(6, args);
    RRender *rc = RRenderContextCreate(o, NULL, 1);
    MeCommandLineOptionsDestroy(o);
    if (!rc) {
        fprintf(stderr, "window_under_xvfb: no window (is Xvfb running? xvfb-run does it)\n");
        return 1;
    }
    const float red[4] = {1, 0, 0, 1};
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, 1}}; /* at Karma's look-at (0, 0, 1) */
    RGraphicBoxCreate(rc, 2, 2, 2, red, tm);
    RRenderSetWindowTitle(rc, "Karma viewer test");
    RRun(rc, tick, NULL);
    unsigned char *rgba = malloc(200 * 150 * 4);
    int status = 0;
    if (ticks != 12) {
        fprintf(stderr, "window_under_xvfb: %d ticks, expected 12\n", ticks);
        status = 1;
    } else if (!rgba || RRenderReadPixels(rc, rgba) != 0) {
        fprintf(stderr, "window_under_xvfb: no frame was drawn\n");
        status = 1;
    } else {
        const unsigned char *centre = rgba + 4 * (75 * 200 + 100), *corner = rgba;
        if (!(centre[0] > 100 && centre[1] < 40 && centre[2] < 40) || corner[0] + corner[1] + corner[2] != 0) {
            fprintf(stderr, "window_under_xvfb: centre (%d, %d, %d) is not red or corner (%d, %d, %d) not black\n",
                    centre[0], centre[1], centre[2], corner[0], corner[1], corner[2]);
            status = 1;
        }
    }
    free(rgba);
    RRenderContextDestroy(rc);
    if (status == 0)
        printf("window opened, 12 frames drawn and shown, closed\n");
    return status;
}
