/* demo_view.h -- a registry scene in the viewer: one graphic per collision model (drawn from its
 * geometry with RGraphicCreateFromModel, following the model's transform), a sphere of the same
 * mass and inertia for each body without a model, and a camera that frames the scene. Shared by `karma render`, `karma view`
 * and the viewer's tests, so the registry stays the one place where a scene is defined. */
#ifndef KARMA_DEMO_VIEW_H
#define KARMA_DEMO_VIEW_H

#include <MeViewer.h>

#include "demo.h"

/** Radius of the sphere drawn for a body without a collision model when its inertia gives none (m);
 *  else the radius of the uniform sphere of its mass and mean moment of inertia. */
#define DEMO_VIEW_MARKER_RADIUS ME_R(0.15)

/** What was drawn for a scene: graphic i stands for body[i] (NULL for a fixed model such as the
 *  ground) and model[i] (NULL for a body drawn as a marker). */
typedef struct DemoView {
    RRender *rc;
    int count;
    RGraphic **graphic;
    MdtBodyID *body;
    McdModelID *model;
} DemoView;

/** Make the graphics of `demo`'s models and bodies in `rc` and frame the camera on them. Returns
 *  MEFALSE (and leaves `view` empty) when memory runs out or a model cannot be drawn. */
MeBool DemoViewCreate(DemoView *view, RRender *rc, const DemoInstance *demo);
/** Point the camera at the scene's bodies and fixed models (planes excluded) from above and aside. */
void DemoViewFrame(DemoView *view, const DemoInstance *demo);
/** The colour the view gives graphic `index` (a palette of distinct hues; fixed models grey). */
void DemoViewColor(const DemoView *view, int index, float color[4]);
/** Delete the graphics (the context and the scene are the caller's). */
void DemoViewDestroy(DemoView *view);

#endif /* KARMA_DEMO_VIEW_H */
