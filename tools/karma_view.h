/* karma_view.h -- the karma tool's viewer commands (built when the viewer is): `render` writes
 * pictures of a scene without a display, `view` opens a window on it; and the tool's usage error,
 * which every command shares. */
#ifndef KARMA_TOOL_VIEW_H
#define KARMA_TOOL_VIEW_H

/** Exit status of a bad command line. */
#define KARMA_EXIT_USAGE 2

/** Prints "karma: " and the message (format with one string argument) and the pointer to
 *  `karma --help` on stderr; returns KARMA_EXIT_USAGE. Defined in karma.c, shared by every command. */
int KarmaUsageError(const char *format, const char *argument);

/** `karma render SCENE [--frames N] [--size WxH] [--out FILE] [--mp4 FILE]`: exit status 0, 1 (scene,
 *  renderer or ffmpeg failed), 2 (bad command line). argv[0] is the scene. */
int KarmaRender(int argc, char **argv);
/** `karma view SCENE [viewer options: -size WxH -timeout N -null -bench -profile [N] -headless ...]`: the
 *  scene in a window, with its help, actions and menu, until it is closed. */
int KarmaView(int argc, char **argv);

#endif /* KARMA_TOOL_VIEW_H */
