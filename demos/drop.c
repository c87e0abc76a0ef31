/* drop.c -- one of each primitive (sphere, box, cylinder, sphyl, cone) dropped on the ground from a
 * tilt; they settle, go to sleep (auto-disable) and their models freeze. */
#include <stdlib.h>

#include "demo.h"

#define SHAPES 5

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 100; /* typical body mass, kg: the world's softness scales with it */
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    McdGeometryID shapes[SHAPES] = {
        McdSphereCreate(fw, ME_R(0.3)),         McdBoxCreate(fw, ME_R(0.6), ME_R(0.4), ME_R(0.3)),
        McdCylinderCreate(fw, ME_R(0.3), ME_R(0.5)), McdSphylCreate(fw, ME_R(0.2), ME_R(0.5)),
        McdConeCreate(fw, ME_R(0.6), ME_R(0.3))};
    static const char *const names[SHAPES] = {"sphere", "box", "cylinder", "sphyl", "cone"};
    /* Mcd's cylinders, sphyls and cones lie along their own z axis: turn it up to y (-90° about x),
     * then tilt each shape a little more about a horizontal axis so that it lands on an edge. */
    MeVector4 upright;
    MeQuaternionMake(upright, (MeVector3){1, 0, 0}, -ME_PI / 2);
    for (int i = 0; i < SHAPES; i++) {
        McdModelID m = DemoAddModel(demo, shapes[i], 800, (MeReal)(i - 2) * ME_R(1.5), ME_R(1.5), 0);
        if (!m)
            return MEFALSE;
        MdtBodyID b = McdModelGetBody(m);
        MeVector4 tilt, q;
        MeQuaternionMake(tilt, (MeVector3){ME_R(0.958), 0, ME_R(-0.287)}, ME_R(0.5) + ME_R(0.2) * (MeReal)i);
        MeQuaternionProduct(q, tilt, upright);
        MdtBodySetQuaternion(b, q[0], q[1], q[2], q[3]);
        demo->named[i] = b;
        demo->names[i] = names[i];
    }
    demo->namedCount = SHAPES;
    return METRUE;
}

static void report(const DemoInstance *demo, FILE *out)
{
    for (int i = 0; i < demo->namedCount; i++) {
        MeVector3 p;
        MdtBodyGetPosition(demo->named[i], p);
        fprintf(out, "  %-8s rests at height %.3f m, %s\n", demo->names[i], (double)p[1],
                MdtBodyIsEnabled(demo->named[i]) ? "still awake" : "asleep (disabled, model frozen)");
    }
}

const DemoScene DemoSceneDrop = {"drop", "a sphere, box, cylinder, sphyl and cone dropped on the ground", 600,
                                 ME_R(1.0) / 60, create, NULL, NULL, report};
