/* MeAppContacts.c -- drawing the world's contacts as lines along their normals, longer with
 * penetration, from a pool of line graphics made once (MeAppDrawContactsInit). */
#include <karma/MeMemory.h>

#include "MeApp.h"
#include "RInternal.h"

/** A contact's line grows by this factor per unit of penetration, as Karma's. */
#define ME_APP_PENETRATION_GAIN ME_R(50.0)

void MEAPI MeAppDrawContactsInit(MeApp *const app, float color[4], int max)
{
    if (!app || !color) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppDrawContactsInit", "the %s is NULL", !app ? "app" : "colour");
        return;
    }
    if (max < 0) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "MeAppDrawContactsInit", "max is %d; it must be 0 or more", max);
        return;
    }
    MeAppContactDrawInfo *d = MeMemoryAPI.createZeroed(sizeof *d);
    RGraphic **lines = MeMemoryAPI.createZeroed(sizeof *lines * (size_t)(max > 0 ? max : 1));
    if (!d || !lines) {
        MeMemoryAPI.destroy(d);
        MeMemoryAPI.destroy(lines);
        R_REPORT(ME_ERR_OUT_OF_MEMORY, "MeAppDrawContactsInit", "no memory for %d contact lines", max);
        return;
    }
    AcmeReal zero[3] = {0, 0, 0};
    for (int i = 0; i < max; i++)
        lines[i] = RGraphicLineCreate(app->rc, zero, zero, color, NULL);
    MeAppContactDrawInfo *old = app->contactDrawInfo;
    if (old) { /* a second call replaces the pool */
        for (int i = 0; i < old->maxContacts; i++)
            if (old->contactG[i])
                RGraphicDelete(app->rc, old->contactG[i], 0);
        MeMemoryAPI.destroy(old->contactG);
        MeMemoryAPI.destroy(old);
    }
    for (int k = 0; k < 4; k++)
        d->color[k] = color[k];
    d->contactG = lines;
    d->maxContacts = max;
    d->length = 1;
    app->contactDrawInfo = d;
}

/* Whether contact drawing was initialised; if not, report it for function fn. */
static MeBool initialised(const MeApp *app, const char *fn)
{
    if (app && app->contactDrawInfo)
        return METRUE;
    R_REPORT(app ? ME_ERR_BAD_STATE : ME_ERR_NULL_ARGUMENT, fn, app ? "call MeAppDrawContactsInit first" : "the app is NULL");
    return MEFALSE;
}

void MEAPI MeAppSetContactDrawLength(MeApp *app, MeReal length)
{
    if (!initialised(app, "MeAppSetContactDrawLength"))
        return;
    if (!(length > 0) || !MeRealIsValid(length)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "MeAppSetContactDrawLength", "length %g is not a positive number", (double)length);
        return;
    }
    app->contactDrawInfo->length = length;
}

/* Shrink line i to a point (hidden). */
static void hide(RGraphic *line)
{
    AcmeReal zero[3] = {0, 0, 0};
    if (line)
        RGraphicLineMoveEnds(line, zero, zero);
}

void MEAPI MeAppToggleDrawContacts(MeApp *app, MeBool d)
{
    if (!initialised(app, "MeAppToggleDrawContacts"))
        return;
    app->drawContacts = d ? METRUE : MEFALSE;
    if (!d)
        for (int i = 0; i < app->contactDrawInfo->maxContacts; i++)
            hide(app->contactDrawInfo->contactG[i]);
}

/* Put contact c on line `line`. */
static void drawContact(const MeAppContactDrawInfo *d, MdtContactID c, RGraphic *line)
{
    MeVector3 p, n, end;
    MdtContactGetPosition(c, p);
    MdtContactGetNormal(c, n);
    MeReal len = d->length * (1 + ME_APP_PENETRATION_GAIN * MdtContactGetPenetration(c));
    for (int k = 0; k < 3; k++)
        end[k] = p[k] + len * n[k];
    if (line)
        RGraphicLineMoveEnds(line, p, end);
}

void MEAPI MeAppDrawContacts(const MeApp *app)
{
    if (!initialised(app, "MeAppDrawContacts"))
        return;
    MeAppContactDrawInfo *d = app->contactDrawInfo;
    int i = 0;
    for (MdtConstraintID c = MdtConstraintGetFirst(app->world); c && i < d->maxContacts; c = MdtConstraintGetNext(c)) {
        MdtContactID single = MdtConstraintDCastContact(c);
        MdtContactGroupID group = MdtConstraintDCastContactGroup(c);
        if (single) {
            drawContact(d, single, d->contactG[i++]);
        } else if (group) {
            for (MdtContactID k = MdtContactGroupGetFirstContact(group); k && i < d->maxContacts;
                 k = MdtContactGroupGetNextContact(group, k))
                drawContact(d, k, d->contactG[i++]);
        }
    }
    d->contactsDrawn = i;
    for (int j = i; j < d->maxContacts; j++)
        hide(d->contactG[j]);
}
