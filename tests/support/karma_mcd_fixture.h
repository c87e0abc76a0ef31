/* karma_mcd_fixture.h -- the one Mcd framework a group of collision tests shares: the group's set-up
 * opens it with the McdInit arguments the file needs, karma_mcd_close (the group's teardown) ends it. */
#ifndef KARMA_MCD_FIXTURE_H
#define KARMA_MCD_FIXTURE_H

#include <karma/Mcd.h>

/** Open *fw = McdInit(0, models, 0, lengthScale) for the group and remember fw for karma_mcd_close.
 *  Returns 0, or -1 when McdInit refused (cmocka then fails the group). */
int karma_mcd_open(McdFrameworkID *fw, int models, MeReal lengthScale);
/** cmocka group teardown: McdTerm the framework karma_mcd_open made and clear the file's handle. */
int karma_mcd_close(void **state);

#endif /* KARMA_MCD_FIXTURE_H */
