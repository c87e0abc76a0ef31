/* profile_global.c -- Karma 1.2's global profiler (see MeProfile.h).
 *
 * One process-wide table of sections, single-threaded like 1.2's: the library itself never feeds
 * it (worlds time themselves in their own MeProfile), so only the program's own calls touch it.
 * Times are kept in nanosecond ticks of the C library's UTC clock (MeProfileDefaultTimer's). */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include <karma/MeMessage.h>
#include <karma/MeProfile.h>

#define MAX_GLOBAL_SECTIONS 64
#define TICKS_PER_SECOND 1000000000ull

typedef struct GlobalSection {
    const char *name;
    unsigned char autoStop;
    MeBool running;
    MeU64 startTicks;
    MeU64 frameTicks;     /* the frame under way */
    MeU64 lastFrameTicks; /* the last completed frame */
    MeU64 totalTicks;     /* all completed frames */
    unsigned long frameCalls, lastFrameCalls, totalCalls;
} GlobalSection;

static struct {
    MeBool timing;
    MeBool insideFrame;
    MeProfileLogModes_enum logging;
    MeProfileOutput output;
    GlobalSection sections[MAX_GLOBAL_SECTIONS];
    int sectionCount;
    unsigned long frames;
} profiler = {METRUE, MEFALSE, kMeProfileDontLog, {kMeProfileOutputAverage, 0.2f, 0}, {{0}}, 0, 0};

/* Integer nanoseconds, not MeProfileDefaultTimer's double seconds: a double holding seconds since
 * 1970 cannot tell apart instants a fraction of a microsecond apart, and a short section read 0. */
static MeU64 nowTicks(void)
{
    struct timespec ts;
    if (timespec_get(&ts, TIME_UTC) == 0)
        return 0;
    return (MeU64)ts.tv_sec * TICKS_PER_SECOND + (MeU64)ts.tv_nsec;
}

static double ticksToMs(MeU64 ticks) { return (double)ticks * 1000.0 / (double)TICKS_PER_SECOND; }

static GlobalSection *findSection(const char *name)
{
    int i;
    for (i = 0; i < profiler.sectionCount; i++)
        if (profiler.sections[i].name == name || strcmp(profiler.sections[i].name, name) == 0)
            return &profiler.sections[i];
    return NULL;
}

static void endSection(GlobalSection *s, MeU64 now)
{
    s->running = MEFALSE;
    s->frameTicks += now - s->startTicks;
}

void MEAPI MeProfileStartTiming(MeProfileTimerMode mode, MeProfileLogModes_enum logging)
{
    (void)mode;
    memset(profiler.sections, 0, sizeof profiler.sections);
    profiler.sectionCount = 0;
    profiler.frames = 0;
    profiler.insideFrame = MEFALSE;
    profiler.logging = logging;
    profiler.timing = METRUE;
}

void MEAPI MeProfileStopTiming(void)
{
    MeProfileTimerMode mode = {0, kMeProfileCounterModeCache, NULL, NULL};
    MeProfileStartTiming(mode, profiler.logging);
    profiler.timing = MEFALSE;
}

void MEAPI MeProfileStartFrame(void)
{
    int i;
    if (profiler.insideFrame)
        MeWarning(3, "MeProfileStartFrame: a frame is already under way (MeProfileEndFrame missing?)");
    for (i = 0; i < profiler.sectionCount; i++) {
        profiler.sections[i].frameTicks = 0;
        profiler.sections[i].frameCalls = 0;
    }
    profiler.insideFrame = METRUE;
}

void MEAPI MeProfileEndFrame(void)
{
    MeU64 now = nowTicks();
    int i;
    for (i = 0; i < profiler.sectionCount; i++) {
        GlobalSection *s = &profiler.sections[i];
        if (s->running) {
            endSection(s, now);
            if (!s->autoStop)
                MeWarning(3, "MeProfileEndFrame: section '%s' was still running at the end of the frame", s->name);
        }
        s->lastFrameTicks = s->frameTicks;
        s->lastFrameCalls = s->frameCalls;
        s->totalTicks += s->frameTicks;
        s->totalCalls += s->frameCalls;
        s->frameTicks = 0;
        s->frameCalls = 0;
    }
    profiler.frames++;
    profiler.insideFrame = MEFALSE;
}

void MEAPI MeProfileStartSectionFn(const char *codeSection, unsigned char autoStop)
{
    GlobalSection *s;
    MeU64 now;
    int i;
    if (!profiler.timing || !codeSection)
        return;
    now = nowTicks();
    for (i = 0; i < profiler.sectionCount; i++)
        if (profiler.sections[i].autoStop && profiler.sections[i].running)
            endSection(&profiler.sections[i], now);
    s = findSection(codeSection);
    if (!s) {
        if (profiler.sectionCount == MAX_GLOBAL_SECTIONS) {
            MeWarning(3, "MeProfileStartSection: no room for section '%s' (at most %d)", codeSection,
                      MAX_GLOBAL_SECTIONS);
            return;
        }
        s = &profiler.sections[profiler.sectionCount++];
        s->name = codeSection;
    }
    s->autoStop = autoStop;
    s->running = METRUE;
    s->frameCalls++;
    s->startTicks = nowTicks();
}

void MEAPI MeProfileEndSectionFn(const char *codeSection)
{
    MeU64 now = nowTicks();
    GlobalSection *s;
    if (!profiler.timing || !codeSection)
        return;
    s = findSection(codeSection);
    if (!s || !s->running) {
        MeWarning(3, "MeProfileEndSection: section '%s' is not running", codeSection);
        return;
    }
    endSection(s, now);
}

void MEAPI MeProfileGetTimerValue(MeProfileTimerResult *const result)
{
    if (!result)
        return;
    result->cpuCycles = nowTicks();
    result->count0 = 0;
    result->count1 = 0;
}

void MEAPI MeProfileStopTimers(void)
{
    MeU64 now = nowTicks();
    int i;
    for (i = 0; i < profiler.sectionCount; i++)
        if (profiler.sections[i].autoStop && profiler.sections[i].running)
            endSection(&profiler.sections[i], now);
}

MeReal MEAPI MeProfileGetSectionTime(const char *codeSection)
{
    const GlobalSection *s = codeSection ? findSection(codeSection) : NULL;
    if (!s)
        return ME_R(0.0);
    return (MeReal)ticksToMs(profiler.logging == kMeProfileLogTotals ? s->totalTicks : s->lastFrameTicks);
}

MeReal MEAPI MeProfileGetAllSectionTime(void)
{
    MeU64 total = 0;
    int i;
    if (profiler.frames == 0)
        return ME_R(0.0);
    for (i = 0; i < profiler.sectionCount; i++)
        total += profiler.sections[i].totalTicks;
    return (MeReal)(ticksToMs(total) / (double)profiler.frames);
}

MeU64 MEAPI MeProfileGetClockSpeed(void) { return TICKS_PER_SECOND; }

void MEAPI MeProfileSetOutputParameters(MeProfileOutput output) { profiler.output = output; }

void MEAPI MeProfileOutputResults(void)
{
    double frames = profiler.frames ? (double)profiler.frames : 1.0;
    int i;
    if (profiler.output.style == kMeProfileOutputGnuplot)
        printf("# section ms_per_frame ms_last_frame calls_per_frame\n");
    else
        printf("Karma profile: %lu frames\n", profiler.frames);
    for (i = 0; i < profiler.sectionCount; i++) {
        const GlobalSection *s = &profiler.sections[i];
        double average = ticksToMs(s->totalTicks) / frames;
        double calls = (double)s->totalCalls / frames;
        switch (profiler.output.style) {
        case kMeProfileOutputGnuplot:
            printf("\"%s\" %.6f %.6f %.3f\n", s->name, average, ticksToMs(s->lastFrameTicks), calls);
            break;
        case kMeProfileOutputEvent:
            printf("  %-24s %10.4f ms/frame %10.4f ms/call\n", s->name, average,
                   s->totalCalls ? ticksToMs(s->totalTicks) / (double)s->totalCalls : 0.0);
            break;
        case kMeProfileOutputNormal:
            printf("  %-24s %10.4f ms/frame, last frame %10.4f ms, %lu calls in %lu frames\n", s->name, average,
                   ticksToMs(s->lastFrameTicks), s->totalCalls, profiler.frames);
            break;
        default:
            printf("  %-24s %10.4f ms/frame\n", s->name, average);
            break;
        }
    }
    fflush(stdout);
}
