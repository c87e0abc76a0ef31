/* hints.c -- the one-time hints of a step that can move nothing: a newcomer's first world (bodies
 * left disabled, gravity left at zero) otherwise sits still without a word. Checked at each step
 * until the world has moved once (usually the first step), so a running world pays nothing. */
#include <karma/MdtWorld.h>

#include "../me/check.h"
#include "body.h"
#include "world.h"

void MdtWorldSetHints(MdtWorldID id, MeBool hints)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (w)
        w->hintsDisabled = !hints;
}

MeBool MdtWorldGetHints(MdtWorldID id)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    return w && !w->hintsDisabled;
}

static MeBool isZero(const MeVector3 v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

/* Something acts on an enabled body: it moves, or a force or torque was applied for this step. */
static MeBool anythingActs(MdtWorldData *w)
{
    if (!isZero(w->gravity) || w->enabledConstraintCount > 0)
        return METRUE;
    for (int i = 0; i < w->bodyPool.capacity; i++) {
        if (!MePoolSlotIsLive(&w->bodyPool, i))
            continue;
        const MdtBodyData *b = MePoolSlot(&w->bodyPool, i);
        if (b->enabled && !(isZero(b->vel) && isZero(b->velrot) && isZero(b->force) && isZero(b->torque)))
            return METRUE;
    }
    return MEFALSE;
}

void MdtWorldHintIfNothingMoves(MdtWorldData *w, const char *function)
{
    if (w->hintsDisabled || w->nothingMovesHinted || w->hasMoved || w->bodyPool.used == 0)
        return;
    if (w->enabledBodyCount == 0) {
        w->nothingMovesHinted = METRUE;
        ME_REPORT_IN(function, ME_ERR_NO_BODY_ENABLED,
                     "the world has %d bodies and none is enabled, so nothing moves: bodies are created "
                     "disabled; call MdtBodyEnable on each (MdtWorldSetHints(world, 0) silences this hint)",
                     w->bodyPool.used);
    } else if (!anythingActs(w)) {
        w->nothingMovesHinted = METRUE;
        ME_REPORT_IN(function, ME_ERR_NOTHING_ACTS,
                     "gravity is zero and nothing acts on the %d enabled bodies, so nothing moves and they "
                     "will fall asleep: gravity is zero until MdtWorldSetGravity sets it (y up: 0, -9.81, 0); "
                     "MdtWorldSetHints(world, 0) silences this hint", w->enabledBodyCount);
    } else {
        w->hasMoved = METRUE;
    }
}
