/* rest_window.c -- the rest window: each enabled body's velocities over its last few tenths of a second,
 * so that auto-disable can judge a body by its mean motion over a window instead of by its last step.
 *
 * Why: a settled heap is never perfectly still. The iterative solver leaves each body of a large
 * partition some velocity noise (several cm/s, changing sign every few steps), harmless to look at
 * but, divided by one step, an "acceleration" of metres per second squared: Karma 1.2's test of the
 * last step's acceleration finds some body of the heap over the threshold at every step, and as a
 * partition sleeps only when every body passes at once, the heap never sleeps. Over a window the noise
 * averages out, while steady motion is judged exactly as 1.2 judges it: a body moving at a constant
 * velocity v has mean velocity v, one under a constant acceleration a has fitted acceleration a, so
 * the public thresholds keep their meaning.
 *
 * The measure, over the averaging time T (MdtWorldSetAutoDisableAveragingTime): the steps are summed
 * in MDT_REST_BLOCKS blocks of k = T / (MDT_REST_BLOCKS h) steps (rounded, at least 1) plus the block
 * being filled. The mean velocity is the mean of all those steps; the acceleration is the slope of
 * the least-squares line through the blocks' mean velocities (each weighted by its steps), which a
 * linear v(t) gives exactly and which noise disturbs far less than an end-to-end difference. A body
 * has a measure only once its blocks are complete (about T after it was enabled or its velocity was
 * set: its window restarts then). The block being filled counts, so a body that starts moving is seen
 * at once. Memory: (MDT_REST_BLOCKS + 1) x 6 reals per body, whatever T. */
#include "world.h"

void MdtBodyRestWindowRestart(MdtBodyData *b)
{
    for (int i = 0; i <= MDT_REST_BLOCKS; i++) {
        b->restCount[i] = 0;
        for (int k = 0; k < 6; k++)
            b->restSum[i][k] = 0;
    }
    b->restNewest = 0;
    b->restFull = 0;
}

int MdtRestWindowBlockSteps(MeReal averagingTime, MeReal h)
{
    if (!(h > 0) || !(averagingTime > 0))
        return 1;
    const MeReal k = averagingTime / (h * MDT_REST_BLOCKS);
    if (k >= ME_R(1e6))
        return 1000000;
    return k < ME_R(1.5) ? 1 : (int)(k + ME_R(0.5));
}

void MdtBodyRestWindowRecord(MdtBodyData *b, int blockSteps)
{
    MeReal *s = b->restSum[b->restNewest];
    for (int k = 0; k < 3; k++) {
        s[k] += b->vel[k];
        s[3 + k] += b->velrot[k];
    }
    if (++b->restCount[b->restNewest] < blockSteps)
        return;
    /* The block is complete: the oldest one's slot becomes the block being filled. */
    b->restNewest = (b->restNewest + 1) % (MDT_REST_BLOCKS + 1);
    b->restCount[b->restNewest] = 0;
    for (int k = 0; k < 6; k++)
        b->restSum[b->restNewest][k] = 0;
    if (b->restFull < MDT_REST_BLOCKS)
        b->restFull++;
}

MeBool MdtBodyRestWindowMeans(const MdtBodyData *b, MeReal h, MeVector3 vel, MeVector3 velrot, MeVector3 accel,
                              MeVector3 accelrot)
{
    if (b->restFull < MDT_REST_BLOCKS || !(h > 0))
        return MEFALSE;
    const int ring = MDT_REST_BLOCKS + 1;
    /* Oldest complete block first, the block being filled last; t = the block's centre, in steps. */
    MeReal total = 0, sum[6] = {0, 0, 0, 0, 0, 0}, tMean = 0, start = 0;
    MeReal centre[MDT_REST_BLOCKS + 1];
    const int oldest = b->restNewest + 1 < ring ? b->restNewest + 1 : 0;
    for (int j = 0, i = oldest; j < ring; j++, i = i + 1 < ring ? i + 1 : 0) { /* i: block j's slot */
        const MeReal n = (MeReal)b->restCount[i];
        centre[j] = start + (n - 1) / 2;
        start += n;
        total += n;
        tMean += n * centre[j];
        for (int k = 0; k < 6; k++)
            sum[k] += b->restSum[i][k];
    }
    tMean /= total;
    MeReal mean[6], slope[6] = {0, 0, 0, 0, 0, 0}, spread = 0;
    for (int k = 0; k < 6; k++)
        mean[k] = sum[k] / total;
    for (int j = 0, i = oldest; j < ring; j++, i = i + 1 < ring ? i + 1 : 0) {
        const MeReal n = (MeReal)b->restCount[i];
        if (n <= 0)
            continue;
        const MeReal dt = centre[j] - tMean;
        spread += n * dt * dt;
        for (int k = 0; k < 6; k++)
            slope[k] += dt * (b->restSum[i][k] - n * mean[k]); /* n dt (block mean - mean) */
    }
    for (int k = 0; k < 3; k++) {
        vel[k] = mean[k];
        velrot[k] = mean[3 + k];
        /* per step -> per second; with one block (k = 1 and nothing else) there is no slope to fit */
        accel[k] = spread > 0 ? slope[k] / (spread * h) : 0;
        accelrot[k] = spread > 0 ? slope[3 + k] / (spread * h) : 0;
    }
    return METRUE;
}
