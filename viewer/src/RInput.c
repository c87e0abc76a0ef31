/* RInput.c -- Karma's PC key map and mouse, and the application's callbacks:
 * arrows Up/Down/Left/Right (a menu's while one is shown), w s a d Up2/Down2/Left2/Right2, h m
 * Enter Space o p actions 0–5 (m shows the default menu when there is one), Esc and Alt+F4 quit, + and −
 * zoom, F1 help, F2 wireframe (Shift+F2 textures), F3 frame-rate lock (Ctrl+F3 frame rate shown), F8 single
 * step (pausing), Ctrl+F8 pause/play, F9 fullscreen (Alt+F9 aspect lock),
 * F12 the viewer's menu, PgUp/PgDn move the look-at point along z; keypad 1 3 7 (Ctrl: 1 3 7 from the
 * other side) and 5 the camera's views and orthographic projection (this library's). Mouse without modifier: left drag orbits, middle drag zooms, right drag
 * pans; with Ctrl, Shift or Alt events go to the application's mouse callback. */
#include <ctype.h>

#include "RInternal.h"

/** Radians of orbit per pixel dragged, metres of zoom per pixel, look-at step of PgUp/PgDn. */
#define R_ORBIT_PER_PIXEL 0.01f
#define R_ZOOM_PER_PIXEL 0.05f
#define R_PAN_PER_PIXEL 0.02f
#define R_KEY_ZOOM 1.0f
#define R_KEY_PAN 0.5f

/** Keypad keys (GLFW's codes) of this library's camera views: 1 front, 3 right, 7 top (Ctrl: the
 *  opposite side), 5 orthographic on and off. */
#define RKEY_KP_1 321
#define RKEY_KP_3 323
#define RKEY_KP_5 325
#define RKEY_KP_7 327

static void setButton(RRender *rc, RButtonList b, RButtonPressCallBack func, void *userdata, char *text)
{
    if (!rc)
        return;
    rc->m_pCallBacks->m_Button[b].m_CallBack = func;
    rc->m_pCallBacks->m_Button[b].m_Userdata = userdata;
    rc->m_pCallBacks->m_Button[b].m_Text = text;
}

void MEAPI RRenderSetUpCallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonUp, f, d, NULL); }
void MEAPI RRenderSetDownCallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonDown, f, d, NULL); }
void MEAPI RRenderSetLeftCallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonLeft, f, d, NULL); }
void MEAPI RRenderSetRightCallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonRight, f, d, NULL); }
void MEAPI RRenderSetUp2CallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonUp2, f, d, NULL); }
void MEAPI RRenderSetDown2CallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonDown2, f, d, NULL); }
void MEAPI RRenderSetLeft2CallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonLeft2, f, d, NULL); }
void MEAPI RRenderSetRight2CallBack(RRender *rc, RButtonPressCallBack f, void *d) { setButton(rc, kRButtonRight2, f, d, NULL); }
void MEAPI RRenderSetUpCallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonUp, f, d, t); }
void MEAPI RRenderSetDownCallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonDown, f, d, t); }
void MEAPI RRenderSetLeftCallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonLeft, f, d, t); }
void MEAPI RRenderSetRightCallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonRight, f, d, t); }
void MEAPI RRenderSetUp2CallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonUp2, f, d, t); }
void MEAPI RRenderSetDown2CallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonDown2, f, d, t); }
void MEAPI RRenderSetLeft2CallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonLeft2, f, d, t); }
void MEAPI RRenderSetRight2CallBackWithText(RRender *rc, RButtonPressCallBack f, void *d, char *t) { setButton(rc, kRButtonRight2, f, d, t); }

void MEAPI RRenderSetActionNCallBackWithText(RRender *rc, int N, RButtonPressCallBack func, void *userdata, char *text)
{
    if (!rc)
        return;
    if (N < 0 || N >= NUM_ACTION_CALLBACKS) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderSetActionNCallBack", "action %d is not 0 to %d", N, NUM_ACTION_CALLBACKS - 1);
        return;
    }
    rc->m_pCallBacks->m_Action[N].m_CallBack = func;
    rc->m_pCallBacks->m_Action[N].m_Userdata = userdata;
    rc->m_pCallBacks->m_Action[N].m_Text = text;
}

void MEAPI RRenderSetActionNCallBack(RRender *rc, int N, RButtonPressCallBack func, void *userdata)
{
    RRenderSetActionNCallBackWithText(rc, N, func, userdata, NULL);
}

void MEAPI RRenderSetJoystickCallBackWithText(RRender *rc, RJoystickCallBack func, void *userdata, char *text)
{
    if (!rc)
        return;
    rc->m_pCallBacks->m_Joystick.m_CallBack = func;
    rc->m_pCallBacks->m_Joystick.m_Userdata = userdata;
    rc->m_pCallBacks->m_Joystick.m_Text = text;
}

void MEAPI RRenderSetJoystickCallBack(RRender *rc, RJoystickCallBack func, void *userdata)
{
    RRenderSetJoystickCallBackWithText(rc, func, userdata, NULL);
}

void MEAPI RRenderSetActionNKey(RRender *rc, const unsigned int N, const char key)
{
    if (!rc)
        return;
    if (N < 2 || N >= NUM_ACTION_CALLBACKS || !isprint((unsigned char)key)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderSetActionNKey", "only actions 2 to %d take a printable key (action %u)",
                 NUM_ACTION_CALLBACKS - 1, N);
        return;
    }
    rc->m_pCallBacks->m_actionKeys[N - 2] = (unsigned char)tolower((unsigned char)key);
}

void MEAPI RRenderSetMouseCallBackWithText(RRender *rc, RMouseCallBack func, void *userdata, char *text)
{
    if (!rc)
        return;
    rc->m_pCallBacks->m_Mouse.m_CallBack = func;
    rc->m_pCallBacks->m_Mouse.m_Userdata = userdata;
    rc->m_pCallBacks->m_Mouse.m_Text = text;
}

void MEAPI RRenderSetMouseCallBack(RRender *rc, RMouseCallBack func, void *userdata)
{
    RRenderSetMouseCallBackWithText(rc, func, userdata, NULL);
}

static void press(RRender *rc, const RCallBackDataButton *b)
{
    if (b->m_CallBack)
        b->m_CallBack(rc, b->m_Userdata);
}

/* The character of a key for the action map (Enter is '\r'), or 0. */
static int keyChar(int key)
{
    if (key == RKEY_ENTER)
        return '\r';
    if (key == ' ' || (key >= '0' && key <= '9'))
        return key;
    if (key >= 'A' && key <= 'Z')
        return key - 'A' + 'a';
    return 0;
}

void RInputKey(RRender *rc, int key, int modifiers)
{
    RRenderCallBacks *cb = rc->m_pCallBacks;
    if (RMenuKey(rc, key)) /* a menu on screen takes the arrows */
        return;
    switch (key) {
    case RKEY_ESCAPE: RRenderQuit(rc); return;
    case RKEY_F4: /* Alt+F4 quits, where the window manager leaves it to the window */
        if (modifiers & RALT)
            RRenderQuit(rc);
        return;
    case RKEY_F1: RRenderToggleUserHelp(rc); return;
    case RKEY_F12: RMenuToggle(rc, rc->m_private->menuShown ? NULL : RViewerMenu(rc)); return;
    case RKEY_F3: /* Ctrl+F3: the frame rate shown; F3: the rate locked */
        if (modifiers & RCONTROL)
            RRenderSetDisplayFps(rc, !rc->m_private->showFps);
        else
            RRenderToggleFrameLock(rc);
        return;
    case RKEY_F9: /* Alt+F9: the aspect kept through resizes; F9: fullscreen */
        if (modifiers & RALT)
            rc->m_private->aspectLock = !rc->m_private->aspectLock;
        else
            RRenderSetFullscreen(rc, !rc->m_private->fullscreen);
        return;
    case RKEY_UP: press(rc, &cb->m_Button[kRButtonUp]); return;
    case RKEY_DOWN: press(rc, &cb->m_Button[kRButtonDown]); return;
    case RKEY_LEFT: press(rc, &cb->m_Button[kRButtonLeft]); return;
    case RKEY_RIGHT: press(rc, &cb->m_Button[kRButtonRight]); return;
    case RKEY_PAGE_UP: RCameraPanZ(rc, R_KEY_PAN); return;
    case RKEY_PAGE_DOWN: RCameraPanZ(rc, -R_KEY_PAN); return;
    case RKEY_KP_ADD: case '=': RCameraZoom(rc, R_KEY_ZOOM); return;
    case RKEY_KP_SUBTRACT: case '-': RCameraZoom(rc, -R_KEY_ZOOM); return;
    case RKEY_KP_1: (modifiers & RCONTROL ? RCameraSetBackView : RCameraSetFrontView)(rc); return;
    case RKEY_KP_3: (modifiers & RCONTROL ? RCameraSetLeftView : RCameraSetRightView)(rc); return;
    case RKEY_KP_7: (modifiers & RCONTROL ? RCameraSetBottomView : RCameraSetTopView)(rc); return;
    case RKEY_KP_5: RCameraSetOrthographic(rc, !RCameraIsOrthographic(rc)); return;
    case RKEY_F2: /* Shift+F2: textures on and off */
        if (modifiers & RSHIFT)
            rc->m_options.m_bTextures = rc->m_options.m_bTextures ? MEFALSE : METRUE;
        else
            RRenderSetWireframe(rc, !rc->m_options.m_bWireFrame);
        return;
    case RKEY_F8:
        if (modifiers & RCONTROL) {
            RRenderSetPause(rc, !rc->m_bPause);
        } else {
            RRenderSetPause(rc, 1);
            RRenderSingleStep(rc);
        }
        return;
    default: break;
    }
    int c = keyChar(key);
    switch (c) {
    case 'w': press(rc, &cb->m_Button[kRButtonUp2]); return;
    case 's': press(rc, &cb->m_Button[kRButtonDown2]); return;
    case 'a': press(rc, &cb->m_Button[kRButtonLeft2]); return;
    case 'd': press(rc, &cb->m_Button[kRButtonRight2]); return;
    case 'h': press(rc, &cb->m_Action[0]); return;
    case 'm': /* the default menu when there is one, else action 1 */
        if (rc->m_private->menuShown) /* whichever menu is shown: hidden */
            RMenuToggle(rc, NULL);
        else if (rc->m_private->menuDefault)
            RMenuDisplay(rc->m_private->menuDefault);
        else
            press(rc, &cb->m_Action[1]);
        return;
    default: break;
    }
    for (int n = 2; c && n < NUM_ACTION_CALLBACKS; n++)
        if (cb->m_actionKeys[n - 2] == c) {
            press(rc, &cb->m_Action[n]);
            return;
        }
}

void RInputMouseButton(RRender *rc, int x, int y, int modifiers, RMouseButtonWhich which, RMouseButtonEvent event)
{
    const RCallBackDataMouse *m = &rc->m_pCallBacks->m_Mouse;
    if (modifiers & (RCONTROL | RSHIFT | RALT)) {
        if (m->m_CallBack)
            m->m_CallBack(rc, x, y, modifiers, which, event, m->m_Userdata);
        return;
    }
    RDrag *drag = &rc->m_private->drag;
    drag->x = x, drag->y = y, drag->active = event == kRNewlyPressed;
}

void RInputMouseMove(RRender *rc, int x, int y, int modifiers, int buttons)
{
    const RCallBackDataMouse *m = &rc->m_pCallBacks->m_Mouse;
    if (modifiers & (RCONTROL | RSHIFT | RALT)) {
        for (int k = 0; k < 3; k++)
            if ((buttons >> k & 1) && m->m_CallBack)
                m->m_CallBack(rc, x, y, modifiers, (RMouseButtonWhich)(k + 1), kRStillPressed, m->m_Userdata);
        return;
    }
    RDrag *drag = &rc->m_private->drag;
    if (!drag->active || !buttons) {
        drag->x = x, drag->y = y;
        return;
    }
    float dx = (float)(x - drag->x), dy = (float)(y - drag->y);
    drag->x = x, drag->y = y;
    if (buttons & 1) {
        RCameraRotateAngle(rc, -dx * R_ORBIT_PER_PIXEL);
        RCameraRotateElevation(rc, dy * R_ORBIT_PER_PIXEL);
    } else if (buttons & 2) {
        RCameraZoom(rc, -dy * R_ZOOM_PER_PIXEL);
    } else if (buttons & 4) {
        RCameraPanX(rc, -dx * R_PAN_PER_PIXEL);
        RCameraPanY(rc, dy * R_PAN_PER_PIXEL);
    }
}
