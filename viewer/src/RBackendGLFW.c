/* RBackendGLFW.c -- a window with an OpenGL 3.3 core context through GLFW; keys and mouse are
 * translated to Karma's key map (RInput.c). */
#include <stdlib.h>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include "RInternal.h"

typedef struct GLFWBackend {
    RBackend base;
    GLFWwindow *window;
    RRender *rc;
    int windowed[4];         /**< x, y, width, height before fullscreen */
} GLFWBackend;

/** Windows open at once: GLFW is terminated when the last closes. */
static int openWindows;

static int modifiersOf(int mods)
{
    return (mods & GLFW_MOD_CONTROL ? RCONTROL : 0) | (mods & GLFW_MOD_SHIFT ? RSHIFT : 0) |
           (mods & GLFW_MOD_ALT ? RALT : 0);
}

static int heldModifiers(GLFWwindow *w)
{
    int m = 0;
    if (glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS)
        m |= RCONTROL;
    if (glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS)
        m |= RSHIFT;
    if (glfwGetKey(w, GLFW_KEY_LEFT_ALT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS)
        m |= RALT;
    return m;
}

static void onKey(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    GLFWBackend *g = glfwGetWindowUserPointer(w);
    if (action == GLFW_PRESS || action == GLFW_REPEAT)
        RInputKey(g->rc, key, modifiersOf(mods)); /* GLFW's key codes are the ones RInput expects */
}

static void onButton(GLFWwindow *w, int button, int action, int mods)
{
    GLFWBackend *g = glfwGetWindowUserPointer(w);
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    RMouseButtonWhich which = button == GLFW_MOUSE_BUTTON_LEFT     ? kRLeftButton
                              : button == GLFW_MOUSE_BUTTON_MIDDLE ? kRMiddleButton
                                                                   : kRRightButton;
    RInputMouseButton(g->rc, (int)x, (int)y, modifiersOf(mods), which,
                      action == GLFW_PRESS ? kRNewlyPressed : kRNewlyReleased);
}

static void onMove(GLFWwindow *w, double x, double y)
{
    GLFWBackend *g = glfwGetWindowUserPointer(w);
    int buttons = (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ? 1 : 0) |
                  (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS ? 2 : 0) |
                  (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ? 4 : 0);
    RInputMouseMove(g->rc, (int)x, (int)y, heldModifiers(w), buttons);
}

static void onResize(GLFWwindow *w, int width, int height)
{
    GLFWBackend *g = glfwGetWindowUserPointer(w);
    if (width > 0 && height > 0) /* 0 × 0 while iconified: keep the picture */
        RRenderResize(g->rc, width, height);
}

static void glfwSwap(RBackend *b, int interval)
{
    glfwMakeContextCurrent(((GLFWBackend *)b)->window);
    glfwSwapInterval(interval);
}

static void glfwFullscreen(RBackend *b, int on)
{
    GLFWBackend *g = (GLFWBackend *)b;
    GLFWmonitor *monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode *mode = monitor ? glfwGetVideoMode(monitor) : NULL;
    if (on && mode && !glfwGetWindowMonitor(g->window)) {
        glfwGetWindowPos(g->window, &g->windowed[0], &g->windowed[1]);
        glfwGetWindowSize(g->window, &g->windowed[2], &g->windowed[3]);
        glfwSetWindowMonitor(g->window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    } else if (!on && glfwGetWindowMonitor(g->window)) {
        glfwSetWindowMonitor(g->window, NULL, g->windowed[0], g->windowed[1], g->windowed[2], g->windowed[3], 0);
    }
}

static void glfwBackendDestroy(RBackend *b)
{
    GLFWBackend *g = (GLFWBackend *)b;
    if (g->window) {
        glfwDestroyWindow(g->window);
        if (--openWindows == 0)
            glfwTerminate();
    }
    free(g);
}

static void glfwCurrent(RBackend *b)
{
    glfwMakeContextCurrent(((GLFWBackend *)b)->window);
}

static int glfwPoll(RBackend *b, RRender *rc)
{
    GLFWBackend *g = (GLFWBackend *)b;
    glfwPollEvents();
    return !glfwWindowShouldClose(g->window);
}

static void glfwPresent(RBackend *b)
{
    glfwSwapBuffers(((GLFWBackend *)b)->window);
}

static void glfwTitle(RBackend *b, const char *title)
{
    glfwSetWindowTitle(((GLFWBackend *)b)->window, title);
}

RBackend *RBackendGLFWCreate(RRender *rc, int width, int height, const char *title)
{
    GLFWBackend *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    if (openWindows == 0 && !glfwInit()) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "no display for a window (try -headless or -null)");
        free(g);
        return NULL;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE); /* the picture follows the framebuffer (RRenderResize) */
    g->window = glfwCreateWindow(width, height, title, NULL, NULL);
    if (!g->window) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "GLFW cannot open a window with OpenGL 3.3 core");
        if (openWindows == 0)
            glfwTerminate();
        free(g);
        return NULL;
    }
    openWindows++;
    g->rc = rc;
    g->base.destroy = glfwBackendDestroy;
    g->base.makeCurrent = glfwCurrent;
    g->base.poll = glfwPoll;
    g->base.present = glfwPresent;
    g->base.setTitle = glfwTitle;
    g->base.setSwapInterval = glfwSwap;
    g->base.setFullscreen = glfwFullscreen;
    g->base.drawsToWindow = 1;
    glfwSetWindowUserPointer(g->window, g);
    glfwSetKeyCallback(g->window, onKey);
    glfwSetMouseButtonCallback(g->window, onButton);
    glfwSetCursorPosCallback(g->window, onMove);
    glfwSetFramebufferSizeCallback(g->window, onResize);
    glfwMakeContextCurrent(g->window);
    glfwSwapInterval(1);
    return &g->base;
}
