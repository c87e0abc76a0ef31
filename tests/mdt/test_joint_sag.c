/* Karma's ε is one world-wide compliance (MdtWorldSetEpsilon: added to the diagonal of every
 * constraint row, 1.2's semantics), so a joint holds a load F like a spring of stiffness γ/(ε h²),
 * whatever the masses: at rest under gravity a body hung from the world sags by
 *     φ = ε m g h² / γ,
 * the steady state of J v⁺ = −γ φ/h − ε λ with v⁺ = 0 and λ = m g h. With Karma's ε = 0.01 / massScale
 * the sag grows with m / massScale (1.4 mm per unit at 60 Hz, γ 0.2): the cause of the soft motorised
 * hinges of issue 17's spinner and tumbler, whose driven bodies weigh 130 to 180 times massScale.
 * Measured here against the formula over three orders of magnitude of mass. */
#include "karma_test.h"

#include <karma/karma.h>

/* Sag (m) of a body of mass m hung on a ball joint at its centre of mass, after 10 s. */
static double sag(MeReal massScale, MeReal m)
{
    MdtWorldID w = MdtWorldCreate(1, 1, 1, massScale);
    assert_non_null(w);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetMass(b, m);
    MdtBodyEnable(b);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, b, NULL);
    MdtBSJointSetPosition(j, 0, 0, 0);
    MdtConstraintEnable(MdtBSJointQuaConstraint(j));
    for (int n = 0; n < 600; n++)
        MdtWorldStep(w, ME_R(1.0) / 60);
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    assert_near(p[0], 0, 1e-9);
    assert_near(p[1], 0, 1e-9);
    MdtWorldDestroy(w);
    return -(double)p[2];
}

static void joint_sag_is_epsilon_m_g_h2_over_gamma(void **state)
{
    (void)state;
    karma_capture_messages(); /* a mass far from massScale is reported: that is the point here */
    const double h = 1.0 / 60, g = 9.81, gamma = 0.2;
    static const double masses[] = {1, 10, 100, 1000};
    for (int k = 0; k < 4; k++) {
        double epsilon = 0.01 / 1.0; /* massScale 1 kg */
        assert_rel(sag(1, (MeReal)masses[k]), epsilon * masses[k] * g * h * h / gamma, ME_TOL(1e-9, 1e-4));
    }
    /* The same body at massScale = its own mass sags as a 1 kg body does at massScale 1. */
    assert_rel(sag(1000, 1000), sag(1, 1), ME_TOL(1e-9, 1e-4));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(joint_sag_is_epsilon_m_g_h2_over_gamma),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
