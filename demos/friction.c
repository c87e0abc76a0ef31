/* friction.c -- blocks on a plane tilted by 20°, side by side, one per friction setting: none,
 * Box friction (a force cap per contact), and NormalForce (Coulomb) with μ below and above tan 20°.
 * The report compares each block's slide with the answer from mechanics. */
#include <math.h>
#include <stdlib.h>

#include "demo.h"

#define TILT ME_R(0.3490658503988659) /* 20° */
#define BLOCK ME_R(0.5)               /* cube edge */
#define DENSITY ME_R(80.0)            /* 10 kg blocks */
#define BOX_CAP ME_R(5.0)             /* N per contact, four contacts */
#define G ME_R(9.81)
#define BLOCKS 4

typedef struct Friction {
    MeMatrix4 inclineTM;
    MeVector3 start[BLOCKS];
    MeVector3 downhill;
} Friction;

static const char *const names[BLOCKS] = {"frictionless", "box cap 4x5 N", "coulomb mu=0.2", "coulomb mu=0.6"};

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 10; /* typical body mass, kg: the world's softness scales with it */
    if (!DemoUniverseCreate(demo, &sizes, G, -1))
        return MEFALSE;
    Friction *s = calloc(1, sizeof *s);
    demo->data = s;
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    MstBridgeID bridge = MstUniverseGetBridge(demo->universe);
    MeReal c = MeCos(TILT), sn = MeSin(TILT);
    /* Rows: the incline's axes in the world (y, its 1 m thickness, is the surface normal: up, tilted
     * towards +z; z, its 40 m length, runs downhill). Its top face passes through the origin. */
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, c, sn, 0}, {0, -sn, c, 0}, {0, -c * ME_R(0.5), -sn * ME_R(0.5), 1}};
    MeMatrix4Copy(s->inclineTM, tm);
    MeVector3Set(s->downhill, 0, -sn, c);
    if (!MstFixedModelCreate(demo->universe, McdBoxCreate(fw, 12, 1, 40), s->inclineTM))
        return MEFALSE;
    McdGeometryID cube = McdBoxCreate(fw, BLOCK, BLOCK, BLOCK);
    MeVector4 q;
    MeQuaternionMake(q, (MeVector3){1, 0, 0}, TILT);
    for (int i = 0; i < BLOCKS; i++) {
        MstMaterialID mat = MstBridgeGetNewMaterial(bridge);
        MdtContactParamsID p = MstBridgeGetContactParams(bridge, 0, mat);
        if (i == 1) {
            MdtContactParamsSetType(p, MdtContactTypeFriction2D);
            MdtContactParamsSetFriction(p, BOX_CAP);
        } else if (i >= 2) {
            MdtContactParamsSetType(p, MdtContactTypeFriction2D);
            MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
            MdtContactParamsSetFrictionCoeffecient(p, i == 2 ? ME_R(0.2) : ME_R(0.6));
        }
        MeReal x = (MeReal)(i - 1.5) * ME_R(1.5);
        /* centre: x along row 0, half a block above the surface along the normal (row 1) */
        MeVector3 pos = {x, tm[1][1] * BLOCK / 2, tm[1][2] * BLOCK / 2};
        McdModelID m = DemoAddModel(demo, cube, DENSITY, pos[0], pos[1], pos[2]);
        if (!m)
            return MEFALSE;
        McdModelSetMaterial(m, mat);
        MdtBodySetQuaternion(McdModelGetBody(m), q[0], q[1], q[2], q[3]);
        MeVector3Copy(s->start[i], pos);
        demo->named[i] = McdModelGetBody(m);
        demo->names[i] = names[i];
    }
    demo->namedCount = BLOCKS;
    return METRUE;
}

static void report(const DemoInstance *demo, FILE *out)
{
    const Friction *s = demo->data;
    MeReal t = demo->time, m = DENSITY * BLOCK * BLOCK * BLOCK;
    MeReal gs = G * MeSin(TILT), gc = G * MeCos(TILT);
    MeReal accel[BLOCKS] = {gs, gs - 4 * BOX_CAP / m, gs - ME_R(0.2) * gc, 0};
    for (int i = 0; i < BLOCKS; i++) {
        MeVector3 p, d;
        MdtBodyGetPosition(demo->named[i], p);
        MeVector3Subtract(d, p, s->start[i]);
        MeReal slid = MeVector3Dot(d, s->downhill);
        MeReal expected = accel[i] > 0 ? accel[i] * t * t / 2 : 0;
        fprintf(out, "  %-16s slid %.3f m in %.2f s (mechanics: %.3f m)\n", demo->names[i], (double)slid, (double)t,
                (double)expected);
    }
}

const DemoScene DemoSceneFriction = {"friction", "blocks on a 20-degree incline, one per friction model", 120,
                                     ME_R(1.0) / 60, create, NULL, NULL, report};
