/* profile.c -- named timed sections (see MeProfile.h). */
#include <string.h>
#include <time.h>

#include <karma/MeProfile.h>

#include "check.h"
#include "profile_at.h"

double MeProfileDefaultTimer(void)
{
    struct timespec ts;
    if (timespec_get(&ts, TIME_UTC) == 0)
        return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void MeProfileInit(MeProfile *profile)
{
    memset(profile, 0, sizeof *profile);
    profile->enabled = METRUE;
    profile->timer = MeProfileDefaultTimer;
}

void MeProfileReset(MeProfile *profile)
{
    MeProfileTimerFn timer = profile->timer;
    MeBool enabled = profile->enabled;
    MeProfileInit(profile);
    profile->timer = timer;
    profile->enabled = enabled;
}

void MeProfileSetTimer(MeProfile *profile, MeProfileTimerFn timer)
{
    profile->timer = timer ? timer : MeProfileDefaultTimer;
}

void MeProfileSetEnabled(MeProfile *profile, MeBool enabled) { profile->enabled = enabled; }

void MeProfileFrameStart(MeProfile *profile)
{
    for (int i = 0; i < profile->sectionCount; i++) {
        MeProfileSection *s = &profile->sections[i];
        s->lastFrameTime = s->frameTime;
        s->frameTime = 0.0;
    }
}

void MeProfileFrameEnd(MeProfile *profile)
{
    for (int i = 0; i < profile->sectionCount; i++) {
        MeProfileSection *s = &profile->sections[i];
        if (s->frameTime > s->maxFrameTime)
            s->maxFrameTime = s->frameTime;
    }
    profile->frames++;
}

/* By pointer first (sections are named by string literals: a step's look-ups then call no strcmp),
 * then by content. */
static int findSection(const MeProfile *profile, const char *name)
{
    for (int i = 0; i < profile->sectionCount; i++)
        if (profile->sections[i].name == name)
            return i;
    for (int i = 0; i < profile->sectionCount; i++)
        if (strcmp(profile->sections[i].name, name) == 0)
            return i;
    return -1;
}

double MeProfileNow(const MeProfile *profile) { return profile->enabled ? profile->timer() : 0.0; }

void MeProfileSectionStartAt(MeProfile *profile, const char *name, double now)
{
    if (!profile->enabled)
        return;
    int i = findSection(profile, name);
    if (i < 0) {
        if (profile->sectionCount == ME_PROFILE_MAX_SECTIONS) {
            ME_REPORT_IN("MeProfileSectionStart", ME_ERR_PROFILE_SECTIONS, "no room for section '%s' (at most %d)",
                         name, ME_PROFILE_MAX_SECTIONS);
            return;
        }
        i = profile->sectionCount++;
        profile->sections[i].name = name;
    }
    if (profile->depth == ME_PROFILE_MAX_DEPTH) {
        ME_REPORT_IN("MeProfileSectionStart", ME_ERR_PROFILE_NESTING, "section '%s' nests deeper than %d", name,
                     ME_PROFILE_MAX_DEPTH);
        return;
    }
    profile->stack[profile->depth] = i;
    profile->startTimes[profile->depth] = now;
    profile->depth++;
}

void MeProfileSectionEndAt(MeProfile *profile, const char *name, double now)
{
    if (!profile->enabled || profile->depth == 0)
        return;
    int top = profile->stack[profile->depth - 1];
    MeProfileSection *s = &profile->sections[top];
    if (s->name != name && strcmp(s->name, name) != 0) {
        ME_REPORT_IN("MeProfileSectionEnd", ME_ERR_PROFILE_NESTING,
                     "ending section '%s' while '%s' is the innermost open one", name, s->name);
        return;
    }
    double elapsed = now - profile->startTimes[profile->depth - 1];
    profile->depth--;
    s->frameTime += elapsed;
    s->totalTime += elapsed;
    s->calls++;
}

void MeProfileSectionStart(MeProfile *profile, const char *name)
{
    MeProfileSectionStartAt(profile, name, MeProfileNow(profile));
}

void MeProfileSectionEnd(MeProfile *profile, const char *name)
{
    MeProfileSectionEndAt(profile, name, MeProfileNow(profile));
}

const MeProfileSection *MeProfileGetSection(const MeProfile *profile, const char *name)
{
    int i = findSection(profile, name);
    return i < 0 ? NULL : &profile->sections[i];
}

double MeProfileGetSectionFrameTime(const MeProfile *profile, const char *name)
{
    const MeProfileSection *s = MeProfileGetSection(profile, name);
    return s ? s->lastFrameTime : 0.0;
}

double MeProfileGetSectionTotal(const MeProfile *profile, const char *name)
{
    const MeProfileSection *s = MeProfileGetSection(profile, name);
    return s ? s->totalTime : 0.0;
}

int MeProfileGetSectionCount(const MeProfile *profile) { return profile->sectionCount; }

const MeProfileSection *MeProfileGetSectionByIndex(const MeProfile *profile, int index)
{
    return (index >= 0 && index < profile->sectionCount) ? &profile->sections[index] : NULL;
}
