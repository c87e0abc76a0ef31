/* demo_view_app.h -- a registry scene as a Karma demo program in the viewer: its help text (F1,
 * with Karma's $ACTION2... names), its actions (Enter resets the scene, Space shoots a ball from
 * the camera towards the look-at point, m shows its options menu, o turns debug drawing on: contacts,
 * joints, shapes and bounding boxes, centres of mass), picking and dragging with the
 * mouse (MeApp), and a step timed in MeProfile's "Collision" and "Dynamics" sections for the
 * performance bar. Every scene of the registry gets all of it: the registry stays the one place
 * where a scene is defined. */
#ifndef KARMA_DEMO_VIEW_APP_H
#define KARMA_DEMO_VIEW_APP_H

#include <MeApp.h>

#include "demo_view.h"

/** Balls kept for shooting; the next shot after the last reuses the oldest. */
#define DEMO_VIEW_APP_BALLS 8
/** The shot ball: radius (m), density (kg/m³) and speed (m/s). */
#define DEMO_VIEW_APP_BALL_RADIUS ME_R(0.25)
#define DEMO_VIEW_APP_BALL_DENSITY ME_R(2000.0)
#define DEMO_VIEW_APP_BALL_SPEED ME_R(15.0)

typedef struct DemoViewApp {
    const DemoScene *scene;
    RRender *rc;
    DemoInstance demo;
    DemoView view;
    MeApp *app;                                  /**< picking and dragging, contact lines */
    McdModelID ball[DEMO_VIEW_APP_BALLS];        /**< shot so far (NULL: not yet) */
    RGraphic *ballGraphic[DEMO_VIEW_APP_BALLS];
    int shots, resets;
    MeBool drawContacts;
    MeBool debugDraw;                            /**< contacts, joints, boxes, centres of mass (o) */
    RMenu *menu;                                 /**< the scene's options (m) */
} DemoViewApp;

/** Build `scene` in `rc` with its help, actions, menu, mouse and performance bar. MEFALSE (and
 *  nothing left) when the scene or its graphics cannot be made. One at a time (the menu's callbacks
 *  find it through a static pointer, as a Karma demo's globals). */
MeBool DemoViewAppCreate(DemoViewApp *a, const DemoScene *scene, RRender *rc);
/** One step of the scene's step size: MeApp's mouse spring, then the step with its collision and
 *  dynamics halves in MeProfile's "Collision" and "Dynamics" sections. */
void DemoViewAppStep(DemoViewApp *a);
/** Shoot a ball from the camera towards the look-at point (scenes with collision; else nothing).
 *  Returns the ball's model, or NULL. */
McdModelID DemoViewAppShoot(DemoViewApp *a);
/** Build the scene again from the registry, as it was at the start (the camera stays). MEFALSE
 *  when it cannot be made (the app is then empty and must only be destroyed). */
MeBool DemoViewAppReset(DemoViewApp *a);
/** Free everything but the context. */
void DemoViewAppDestroy(DemoViewApp *a);

#endif /* KARMA_DEMO_VIEW_APP_H */
