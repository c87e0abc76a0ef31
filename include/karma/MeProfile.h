/* MeProfile.h -- named, timed sections of work, per frame and in total: Karma 1.2's global profiler,
 * and the per-world profiles of this library.
 *
 * The global profiler (MeProfileStartSection(name, autoStop), MeProfileGetSectionTime(name)...) is
 * Karma 1.2's: one set of sections for the whole program, fed by the program itself, single-threaded
 * (call it from one thread). It is running from the start (as though MeProfileStartTiming had been
 * called with kMeProfileDontLog); MeProfileStopTiming stops it. Times it returns are milliseconds.
 *
 * A per-world profile (struct MeProfile, functions taking a MeProfile * first) holds up to ME_PROFILE_MAX_SECTIONS named sections. Each world owns one, and times every
 * stage of its step in it ("Partition", "AutoDisable", "Pack", "Solve", "Integrate", "Unpack");
 * collision and the bridge add theirs ("Farfield", "Nearfield"...). Karma's grouped names
 * ("Collision", "Dynamics", "Rendering", "Idle Time") feed the viewer's performance bar.
 * Sections may nest; each records its own inclusive time. Times are in seconds. */
#ifndef ME_PROFILE_H
#define ME_PROFILE_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

#define ME_PROFILE_MAX_SECTIONS 32
#define ME_PROFILE_MAX_DEPTH 8

typedef struct MeProfileSection {
    const char *name;   /**< string literal or a string that outlives the profile */
    double frameTime;   /**< seconds spent in the section during the current/last frame */
    double lastFrameTime; /**< the completed previous frame */
    double totalTime;   /**< seconds since creation or reset */
    double maxFrameTime;
    unsigned long calls;
} MeProfileSection;

/** A clock returning seconds; replace it for a platform with a better timer. */
typedef double (*MeProfileTimerFn)(void);

typedef struct MeProfile {
    MeProfileSection sections[ME_PROFILE_MAX_SECTIONS];
    int sectionCount;
    int stack[ME_PROFILE_MAX_DEPTH];
    double startTimes[ME_PROFILE_MAX_DEPTH];
    int depth;
    unsigned long frames;
    MeBool enabled;
    MeProfileTimerFn timer;
} MeProfile;

/** The default clock (C11 timespec_get, wall time, seconds). */
ME_API double MeProfileDefaultTimer(void);

/** Set up an empty profile (no sections, timing on, the default timer); Reset clears its times;
 *  SetTimer replaces its clock (NULL: the default). */
ME_API void MeProfileInit(MeProfile *profile);
/** Clear every section and time, keeping the timer and the enabled state. */
ME_API void MeProfileReset(MeProfile *profile);
/** Replace the clock (seconds; NULL: MeProfileDefaultTimer). */
ME_API void MeProfileSetTimer(MeProfile *profile, MeProfileTimerFn timer);
/** Turn timing on or off (on by default); when off, sections cost one branch. */
ME_API void MeProfileSetEnabled(MeProfile *profile, MeBool enabled);
/** Begin a new frame: each section's frame time moves to lastFrameTime and restarts at zero. */
ME_API void MeProfileFrameStart(MeProfile *profile);
/** End the frame: each section's longest frame time is updated and the frame count grows. */
ME_API void MeProfileFrameEnd(MeProfile *profile);
/** Start/end the section called `name` (created on first use). */
ME_API void MeProfileSectionStart(MeProfile *profile, const char *name);
/** End section `name`; ending one that is not the innermost open section refused (ME_ERR_PROFILE_NESTING). */
ME_API void MeProfileSectionEnd(MeProfile *profile, const char *name);
/** The section called `name`, or NULL. */
ME_API const MeProfileSection *MeProfileGetSection(const MeProfile *profile, const char *name);
/** Seconds spent in `name` during the last completed frame (0 if unknown). */
ME_API double MeProfileGetSectionFrameTime(const MeProfile *profile, const char *name);
/** Seconds spent in `name` over every frame since Init or Reset (0 if unknown). */
ME_API double MeProfileGetSectionTotal(const MeProfile *profile, const char *name);
/** Number of sections created. */
ME_API int MeProfileGetSectionCount(const MeProfile *profile);
/** Section `index` (a pointer into the profile, valid while it lives), or NULL outside 0 ... count − 1. */
ME_API const MeProfileSection *MeProfileGetSectionByIndex(const MeProfile *profile, int index);

/* ======================================================== Karma 1.2's global profiler */

/** How MeProfileOutputResults lays out its report. */
typedef enum {
    kMeProfileOutputAverage, /**< per section: average time a frame (default) */
    kMeProfileOutputEvent,   /**< per section: average a frame and a call */
    kMeProfileOutputNormal,  /**< every figure, one section a line */
    kMeProfileOutputGnuplot  /**< whitespace-separated columns, for plotting */
} MeProfileOutput_enum;

/** Hardware counter selection of Karma's consoles (accepted and ignored here). */
typedef enum { kMeProfileCounterModeFlops, kMeProfileCounterModeCache } MeProfileCounterModes_enum;

/** What is kept across frames. */
typedef enum {
    kMeProfileDontLog,  /**< the last completed frame only */
    kMeProfileLogAll,   /**< the last frame, and totals over all frames */
    kMeProfileLogTotals /**< totals: MeProfileGetSectionTime gives the sum over all frames */
} MeProfileLogModes_enum;

/** A timer reading: cpuCycles counts ticks of MeProfileGetClockSpeed() a second (nanoseconds here);
 *  the hardware counters are 0. */
typedef struct {
    MeU64 cpuCycles;
    MeU64 count0;
    MeU64 count1;
} MeProfileTimerResult;

/** Timer set-up of Karma's consoles (accepted and ignored here). */
typedef struct {
    unsigned granularity;
    MeProfileCounterModes_enum counterMode;
    const char **count0Label;
    const char **count1Label;
} MeProfileTimerMode;

/** Report style. */
typedef struct {
    MeProfileOutput_enum style;
    float jaggedness; /**< gnuplot styling (unused) */
    unsigned settletime; /**< frames skipped before averaging in reports */
} MeProfileOutput;

/** Forget all sections and (re)start timing with the given logging. */
ME_API void MEAPI MeProfileStartTiming(MeProfileTimerMode mode, MeProfileLogModes_enum logging);
/** Stop timing and forget all sections; sections are ignored until MeProfileStartTiming. */
ME_API void MEAPI MeProfileStopTiming(void);
/** A frame begins: the sections' frame times restart at zero. */
ME_API void MEAPI MeProfileStartFrame(void);
/** The frame ends: sections still running are ended (with a warning), the frame's times become the
 *  last frame's and are added to the totals. */
ME_API void MEAPI MeProfileEndFrame(void);

/** Start timing the section called codeSection (created on first use; the string must outlive the
 *  profiler). With autoStop 1 it ends by itself at the next MeProfileStartSection; with 0 call
 *  MeProfileEndSection. Sections may overlap. Compiled out when _ME_NOPROFILING is defined. */
#ifdef _ME_NOPROFILING
#  define MeProfileStartSection(x, y) ((void)0)
#  define MeProfileEndSection(x) ((void)0)
#else
#  define MeProfileStartSection(x, y) MeProfileStartSectionFn((x), (y))
#  define MeProfileEndSection(x) MeProfileEndSectionFn(x)
#endif
/** Start the section called codeSection (a literal: its address is kept). With autoStop set, the
 *  section ends by itself when the next section starts or the frame ends. */
ME_API void MEAPI MeProfileStartSectionFn(const char *codeSection, unsigned char autoStop);
/** End the running section called codeSection (a warning if it is not running). */
ME_API void MEAPI MeProfileEndSectionFn(const char *codeSection);
/** Read the timer. */
ME_API void MEAPI MeProfileGetTimerValue(MeProfileTimerResult *const result);
/** End every running autoStop section (call before MeProfileEndFrame). */
ME_API void MEAPI MeProfileStopTimers(void);
/** Print every section's figures to stdout in the chosen style. */
ME_API void MEAPI MeProfileOutputResults(void);
/** Milliseconds in codeSection in the last completed frame (kMeProfileLogTotals: over all frames);
 *  0 for an unknown section. */
ME_API MeReal MEAPI MeProfileGetSectionTime(const char *codeSection);
/** Milliseconds a frame in all sections together, averaged over the frames timed. */
ME_API MeReal MEAPI MeProfileGetAllSectionTime(void);
/** Timer ticks a second. */
ME_API MeU64 MEAPI MeProfileGetClockSpeed(void);
/** Choose the report style. */
ME_API void MEAPI MeProfileSetOutputParameters(MeProfileOutput output);

/* Karma's PS2 low-overhead timers: nothing elsewhere. */
#define ticInit(countType0, countType1) ((void)0)
#define tic(name) ((void)0)
#define ticOutputResults(filename) ((void)0)
#define ticCleanup() ((void)0)

ME_EXTERN_C_END

#endif /* ME_PROFILE_H */
