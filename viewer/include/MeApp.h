/* MeApp.h -- Karma's demo support (library karma_viewer): picking a body with the mouse and dragging
 * it with a mouse spring, and drawing contacts. Karma 1.2's names and argument orders.
 *
 *     app = MeAppCreateFromUniverse(universe, rc);
 *     RRenderSetMouseCallBack(rc, MeAppMousePickCB, app);   (Ctrl/Shift/Alt + left button drags)
 *     tick: MeAppStep(app); MstUniverseStep(universe, dt);
 *     RRenderContextDestroy(rc) and MeAppDestroy(app), in either order.
 *
 * Mouse positions are the viewer's: window pixels, origin at the top left. */
#ifndef ME_APP_H
#define ME_APP_H

#include <karma/Mst.h>

#include "MeAppTypes.h"
#include "MeViewer.h"

ME_EXTERN_C_BEGIN

/** Demo support for a universe's world and space, drawing in rc. NULL (with a message) when u or rc
 *  is NULL or memory runs out. */
MeApp *MEAPI MeAppCreateFromUniverse(const MstUniverseID u, RRender *rc);
/** The universe given to MeAppCreateFromUniverse (NULL for MeAppCreate's). */
MstUniverseID MEAPI MeAppGetMstUniverse(MeApp *app);
/** Demo support for a world and a space (NULL space: nothing can be picked), drawing in rc. NULL
 *  (with a message) when world or rc is NULL or memory runs out. Spring gains 25 and 2.8 per kg. */
MeApp *MEAPI MeAppCreate(const MdtWorldID world, const McdSpaceID space, RRender *rc);
/** Free the app (its graphics belong to the render context, which frees them). NULL is accepted. */
void MEAPI MeAppDestroy(MeApp *const app);

/** Draw up to `max` contacts (≥ 0) as lines of `color` along their normals (see
 *  MeAppSetContactDrawLength), updated by MeAppStep once MeAppToggleDrawContacts(app, 1). */
void MEAPI MeAppDrawContactsInit(MeApp *const app, float color[4], int max);
/** Move the contact lines to the world's current contacts: from the contact point along its normal,
 *  length·(1 + 50·penetration); lines not needed shrink to a point. */
void MEAPI MeAppDrawContacts(const MeApp *app);
/** Draw contacts (d true) or hide them. Needs MeAppDrawContactsInit first. */
void MEAPI MeAppToggleDrawContacts(MeApp *app, MeBool d);
/** Length of a contact's line without penetration (world units, > 0). */
void MEAPI MeAppSetContactDrawLength(MeApp *app, MeReal length);

/** Unit direction (world) from the camera through window pixel (x, y). */
void MEAPI MeAppFindClickDir(const MeApp *const app, int x, int y, MeVector3 normClickDir);
/** The world point under window pixel (x, y) on the near clipping plane. */
void MEAPI MeAppFindClickPos(const MeApp *const app, int x, int y, MeVector3 clickPos);
/** The collision model under window pixel (x, y): the first met by a 500-unit segment from the
 *  camera through the pixel (orth: from the near plane along the view direction). Fills
 *  normClickDir (the direction) and pos (where it was met); NULL when nothing is there. */
McdModelID MEAPI MeAppPickMcdModel(const MeApp *const app, int x, int y, MeVector3 normClickDir, MeVector3 pos,
                                   MeBool orth);
/** Apply the mouse spring to the dragged body (MeAppStep calls it): at the grabbed point the force
 *  mass·(stiffness·(desired − point) − damping·velocity of the point), plus −mass·gravity so the
 *  spring carries the body; keeps the body enabled and moves the rubber band. */
void MEAPI MeAppUpdateMouseSpring(MeApp *app);
/** The mouse callback (RRenderSetMouseCallBack(rc, MeAppMousePickCB, app)): left press picks the
 *  body under the cursor, moves drag the grabbed point at its distance from the camera, release
 *  (or another button) lets go. */
void MEAPI MeAppMousePickCB(RRender *rc, int x, int y, int modifiers, RMouseButtonWhich which,
                            RMouseButtonEvent event, void *userdata);
/** Once per tick, before stepping: the mouse spring, and the contacts when drawn. */
void MEAPI MeAppStep(MeApp *app);

ME_EXTERN_C_END

#endif /* ME_APP_H */
