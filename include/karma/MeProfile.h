/* MeProfile.h -- named, timed sections of work, per frame and in total.
 *
 * A profile holds up to ME_PROFILE_MAX_SECTIONS named sections. Each world owns one, and times every
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

ME_API void MeProfileInit(MeProfile *profile);
ME_API void MeProfileReset(MeProfile *profile);
ME_API void MeProfileSetTimer(MeProfile *profile, MeProfileTimerFn timer);
/** Turn timing on or off (on by default); when off, sections cost one branch. */
ME_API void MeProfileSetEnabled(MeProfile *profile, MeBool enabled);
/** Begin a new frame: each section's frame time moves to lastFrameTime and restarts at zero. */
ME_API void MeProfileFrameStart(MeProfile *profile);
ME_API void MeProfileFrameEnd(MeProfile *profile);
/** Start/end the section called `name` (created on first use). */
ME_API void MeProfileStartSection(MeProfile *profile, const char *name);
ME_API void MeProfileEndSection(MeProfile *profile, const char *name);
/** The section called `name`, or NULL. */
ME_API const MeProfileSection *MeProfileGetSection(const MeProfile *profile, const char *name);
/** Seconds spent in `name` during the last completed frame (0 if unknown). */
ME_API double MeProfileGetSectionTime(const MeProfile *profile, const char *name);
ME_API double MeProfileGetSectionTotal(const MeProfile *profile, const char *name);
ME_API int MeProfileGetSectionCount(const MeProfile *profile);
ME_API const MeProfileSection *MeProfileGetSectionByIndex(const MeProfile *profile, int index);

ME_EXTERN_C_END

#endif /* ME_PROFILE_H */
