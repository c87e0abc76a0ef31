/* RBackendEGL.c -- an OpenGL 3.3 core context without a display: EGL on Mesa's surfaceless
 * platform (or the first EGL device), drawing only into framebuffer objects. */
#include <stdlib.h>

#include <epoxy/egl.h>

#include "RInternal.h"

typedef struct EGLBackend {
    RBackend base;
    EGLDisplay display;
    EGLContext context;
} EGLBackend;

static void eglDestroy(RBackend *b)
{
    EGLBackend *e = (EGLBackend *)b;
    if (e->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(e->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (e->context != EGL_NO_CONTEXT)
            eglDestroyContext(e->display, e->context);
        /* No eglTerminate: the display is the process's one surfaceless display, shared by every
         * headless context; terminating it would pull it from under the others. */
        eglReleaseThread();
    }
    free(e);
}

static void eglCurrent(RBackend *b)
{
    EGLBackend *e = (EGLBackend *)b;
    eglMakeCurrent(e->display, EGL_NO_SURFACE, EGL_NO_SURFACE, e->context);
}

/* Mesa's surfaceless platform first (no GPU, no display needed); else the first EGL device. */
static EGLDisplay openDisplay(void)
{
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, NULL, NULL))
            return d;
    }
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[4];
        EGLint n = 0;
        if (eglQueryDevicesEXT(4, devices, &n) && n > 0) {
            EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], NULL);
            if (d != EGL_NO_DISPLAY && eglInitialize(d, NULL, NULL))
                return d;
        }
    }
    return EGL_NO_DISPLAY;
}

RBackend *RBackendEGLCreate(void)
{
    EGLBackend *e = calloc(1, sizeof *e);
    if (!e)
        return NULL;
    e->base.destroy = eglDestroy;
    e->base.makeCurrent = eglCurrent;
    e->context = EGL_NO_CONTEXT;
    e->display = openDisplay();
    if (e->display == EGL_NO_DISPLAY) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate",
                 "no EGL display: headless drawing needs Mesa's EGL (Debian: libegl-mesa0 libgl1-mesa-dri)");
        eglDestroy(&e->base);
        return NULL;
    }
    static const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = NULL;
    EGLint count = 0;
    if (!eglChooseConfig(e->display, configAttributes, &config, 1, &count) || count < 1)
        config = NULL; /* contexts without a config (EGL_KHR_no_config_context) */
    static const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                               EGL_NONE};
    if (eglBindAPI(EGL_OPENGL_API))
        e->context = eglCreateContext(e->display, config ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
    if (e->context == EGL_NO_CONTEXT ||
        !eglMakeCurrent(e->display, EGL_NO_SURFACE, EGL_NO_SURFACE, e->context)) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "EGL cannot make an OpenGL 3.3 core context (error 0x%x)",
                 (unsigned)eglGetError());
        eglDestroy(&e->base);
        return NULL;
    }
    return &e->base;
}
