/* MeApp.c -- Karma's demo support object: one world and space (or universe), one render context, the
 * mouse spring's state and the contact lines. MeAppStep runs the per-tick parts. */
#include <karma/MeMemory.h>

#include "MeApp.h"
#include "RInternal.h"

/** Karma 1.2's mouse-spring gains, per unit of the dragged body's mass. */
#define ME_APP_SPRING_STIFFNESS ME_R(25.0)
#define ME_APP_SPRING_DAMPING ME_R(2.8)

MeApp *MEAPI MeAppCreateFromUniverse(const MstUniverseID u, RRender *rc)
{
    if (!u) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppCreateFromUniverse", "the universe is NULL");
        return NULL;
    }
    MeApp *app = MeAppCreate(MstUniverseGetWorld(u), MstUniverseGetSpace(u), rc);
    if (app)
        app->universe = u;
    return app;
}

MstUniverseID MEAPI MeAppGetMstUniverse(MeApp *app)
{
    if (!app) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppGetMstUniverse", "the app is NULL");
        return NULL;
    }
    return app->universe;
}

MeApp *MEAPI MeAppCreate(const MdtWorldID world, const McdSpaceID space, RRender *rc)
{
    if (!world || !rc) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppCreate", "the %s is NULL", !world ? "world" : "render context");
        return NULL;
    }
    MeApp *app = MeMemoryAPI.createZeroed(sizeof *app);
    if (!app) {
        R_REPORT(ME_ERR_OUT_OF_MEMORY, "MeAppCreate", "no memory for the app");
        return NULL;
    }
    static const float white[4] = {1, 1, 1, 1};
    AcmeReal zero[3] = {0, 0, 0};
    app->world = world;
    app->space = space;
    app->rc = rc;
    app->mouseInfo.mouseSpringStiffness = ME_APP_SPRING_STIFFNESS;
    app->mouseInfo.mouseSpringDamping = ME_APP_SPRING_DAMPING;
    app->mouseInfo.line = RGraphicLineCreate(rc, zero, zero, white, NULL);
    return app;
}

void MEAPI MeAppDestroy(MeApp *const app)
{
    if (!app)
        return;
    if (app->contactDrawInfo) {
        MeMemoryAPI.destroy(app->contactDrawInfo->contactG);
        MeMemoryAPI.destroy(app->contactDrawInfo);
    }
    MeMemoryAPI.destroy(app);
}

void MEAPI MeAppStep(MeApp *app)
{
    if (!app) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppStep", "the app is NULL");
        return;
    }
    MeAppUpdateMouseSpring(app);
    if (app->drawContacts && app->contactDrawInfo)
        MeAppDrawContacts(app);
}
