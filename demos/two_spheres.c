/* two_spheres.c -- Karma 1.2's TwoSpheres sample: two spheres meet head-on in a world without
 * gravity, through the whole pipeline (farfield pair, nearfield contact, contact group, solver).
 * The report checks momentum conservation and the restitution set in the material table. */
#include <stdlib.h>

#include "demo.h"

#define RESTITUTION ME_R(0.8)
#define SPEED ME_R(2.0)

typedef struct TwoSpheres {
    MeReal momentum0, energy0;
} TwoSpheres;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 500; /* typical body mass, kg: the world's softness scales with it */
    if (!DemoUniverseCreate(demo, &sizes, 0, -1))
        return MEFALSE;
    TwoSpheres *s = calloc(1, sizeof *s);
    demo->data = s;
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(demo->universe), 0, 0);
    MdtContactParamsSetRestitution(p, RESTITUTION);
    McdModelID a = DemoAddModel(demo, McdSphereCreate(fw, 0.5f), 1000, -2, 0, 0);
    McdModelID b = DemoAddModel(demo, McdSphereCreate(fw, 0.5f), 1000, 2, 0, 0);
    if (!a || !b)
        return MEFALSE;
    demo->named[0] = McdModelGetBody(a);
    demo->names[0] = "left";
    demo->named[1] = McdModelGetBody(b);
    demo->names[1] = "right";
    demo->namedCount = 2;
    MdtBodySetLinearVelocity(demo->named[0], SPEED, 0, 0);
    MdtBodySetLinearVelocity(demo->named[1], -SPEED, 0, 0);
    s->momentum0 = 0;
    s->energy0 = MdtBodyGetKineticEnergy(demo->named[0]) + MdtBodyGetKineticEnergy(demo->named[1]);
    return METRUE;
}

static void report(const DemoInstance *demo, FILE *out)
{
    MeVector3 va, vb;
    MdtBodyGetLinearVelocity(demo->named[0], va);
    MdtBodyGetLinearVelocity(demo->named[1], vb);
    MeReal m = MdtBodyGetMass(demo->named[0]);
    fprintf(out, "  velocities after the collision: left %.4f m/s, right %.4f m/s\n", (double)va[0], (double)vb[0]);
    fprintf(out, "  momentum: %.3g kg m/s (was 0)\n", (double)(m * (va[0] + vb[0])));
    fprintf(out, "  restitution: separation/approach speed %.4f (material: %.2f)\n",
            (double)((vb[0] - va[0]) / (2 * SPEED)), (double)RESTITUTION);
}

const DemoScene DemoSceneTwoSpheres = {
    "twospheres", "two spheres collide head-on (Karma's TwoSpheres sample)", 180, ME_R(1.0) / 60, create,
    NULL, NULL, report};
