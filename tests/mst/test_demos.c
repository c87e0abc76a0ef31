/* Every registered demo scene (demos/registry.c) runs 600 steps at its own step size with finite
 * state and no warning: the scenes are the library's widest smoke test, and what users run first. */
#include "karma_test.h"

#include <math.h>

#include <karma/karma.h>

#include "demo.h"

#define STEPS 600

/* Every body of the world has a finite position, quaternion and velocities; returns the count. */
static int checkFinite(MdtWorldID world, const char *scene, double *maxSpeed)
{
    int n = 0;
    for (MdtBodyID b = MdtBodyGetFirst(world); b; b = MdtBodyGetNext(b)) {
        MeVector3 x, v, w;
        MeVector4 q;
        MdtBodyGetPosition(b, x);
        MdtBodyGetQuaternion(b, q);
        MdtBodyGetLinearVelocity(b, v);
        MdtBodyGetAngularVelocity(b, w);
        MeReal all[13] = {x[0], x[1], x[2], q[0], q[1], q[2], q[3], v[0], v[1], v[2], w[0], w[1], w[2]};
        for (int k = 0; k < 13; k++)
            if (!isfinite(all[k]))
                fail_msg("scene %s: body %d has a non-finite state value (%d)", scene, n, k);
        double speed = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
        if (speed > *maxSpeed)
            *maxSpeed = speed;
        n++;
    }
    return n;
}

static void every_demo_runs_clean(void **state)
{
    (void)state;
    assert_true(DemoSceneCount() > 0);
    for (int i = 0; i < DemoSceneCount(); i++) {
        const DemoScene *scene = DemoSceneAt(i);
        assert_non_null(scene);
        karma_capture_messages();
        DemoInstance demo;
        assert_true(DemoCreate(scene, &demo));
        for (int step = 0; step < STEPS; step++)
            DemoStep(&demo, scene->defaultStepSize);
        double maxSpeed = 0;
        int bodies = checkFinite(demo.world, scene->name, &maxSpeed);
        unsigned long warnings = karma_warning_count();
        printf("%-12s %4d bodies, %d steps of %.4f s: %lu warnings, fastest body %.3f m/s\n", scene->name, bodies,
               STEPS, (double)scene->defaultStepSize, warnings, maxSpeed);
        if (warnings != 0)
            fail_msg("scene %s reported %lu warning(s); last message: %s", scene->name, warnings, karma_last_text());
        assert_true(bodies > 0);
        DemoDestroy(&demo);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_demo_runs_clean),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
