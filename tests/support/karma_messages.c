/* karma_messages.c -- a quiet message handler that records what Karma reported, for tests. */
#include <string.h>

#include "karma_test.h"

#include <karma/MdtBody.h>

static MeErrorCode lastCode = ME_ERR_NONE;
static char lastText[512];
static char lastFunction[128];
static unsigned long warnings;

static void recorder(const MeMessageInfo *info, void *user)
{
    (void)user;
    lastCode = info->code;
    snprintf(lastText, sizeof lastText, "%s", info->text);
    snprintf(lastFunction, sizeof lastFunction, "%s", info->function ? info->function : "");
    if (info->level >= ME_LEVEL_WARNING)
        warnings++;
    if (info->level == ME_LEVEL_FATAL)
        MeDefaultMessageHandler(info, NULL);
}

void karma_capture_messages(void)
{
    MeSetMessageHandler(recorder, NULL, NULL);
    MeSetMessageLevel(ME_LEVEL_DEBUG);
    MeMessageResetCounts();
    lastCode = ME_ERR_NONE;
    lastText[0] = lastFunction[0] = '\0';
    warnings = 0;
}

MeErrorCode karma_last_code(void) { return lastCode; }
const char *karma_last_text(void) { return lastText; }
const char *karma_last_function(void) { return lastFunction; }
unsigned long karma_warning_count(void) { return warnings; }

uint64_t karma_hash_bytes(uint64_t hash, const void *data, size_t size)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < size; i++) {
        hash ^= p[i];
        hash *= 1099511628211ull;
    }
    return hash;
}

uint64_t karma_hash_world(uint64_t hash, MdtWorldID world)
{
    for (MdtBodyID b = MdtBodyGetFirst(world); b; b = MdtBodyGetNext(b)) {
        MeVector3 x, v, w;
        MeVector4 q;
        MeBool enabled = MdtBodyIsEnabled(b);
        MdtBodyGetPosition(b, x);
        MdtBodyGetQuaternion(b, q);
        MdtBodyGetLinearVelocity(b, v);
        MdtBodyGetAngularVelocity(b, w);
        hash = karma_hash_bytes(hash, x, sizeof x);
        hash = karma_hash_bytes(hash, q, sizeof q);
        hash = karma_hash_bytes(hash, v, sizeof v);
        hash = karma_hash_bytes(hash, w, sizeof w);
        hash = karma_hash_bytes(hash, &enabled, sizeof enabled);
    }
    return hash;
}
