/* profile_at.h -- profile sections timed from a clock reading the caller takes (internal): where one
 * section ends and the next begins (a world's stages, collision's parts), one reading serves both,
 * and a step reads the clock about half as often (each reading costs tens of nanoseconds). */
#ifndef ME_PROFILE_AT_H
#define ME_PROFILE_AT_H

#include <karma/MeProfile.h>

/* The profile's clock (seconds), or 0 when the profile is off (then nothing is read). */
double MeProfileNow(const MeProfile *profile);
/* MeProfileSectionStart and MeProfileSectionEnd at the time `now` (a reading of MeProfileNow). */
void MeProfileSectionStartAt(MeProfile *profile, const char *name, double now);
void MeProfileSectionEndAt(MeProfile *profile, const char *name, double now);

#endif /* ME_PROFILE_AT_H */
