/* bench_karma.c -- what every Karma bench driver sets up the same way (see bench_karma.h). */
#include "bench_karma.h"

void bench_karma_contact_defaults(MstUniverseID u, double mu)
{
    MdtContactParamsID params = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetType(params, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(params, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(params, (MeReal)mu);
    MdtContactParamsSetRestitution(params, 0);
}

McdModelID bench_karma_body(MstUniverseID u, McdGeometryID g, double mass, const double inertia[3],
                            const double pos[3], const double quat[4])
{
    /* the density only seeds the mass properties, replaced just below by the scene's */
    McdModelID m = g ? MstModelAndBodyCreate(u, g, 1) : NULL;
    if (!m)
        return NULL;
    MdtBodyID body = McdModelGetBody(m);
    MeMatrix3 I = {{(MeReal)inertia[0], 0, 0}, {0, (MeReal)inertia[1], 0}, {0, 0, (MeReal)inertia[2]}};
    MeVector3 origin = {0, 0, 0};
    MdtBodySetMass(body, (MeReal)mass);
    MdtBodySetInertiaTensor(body, I);
    MdtBodyEnableNonSphericalInertia(body);
    MdtBodySetCenterOfMassRelativePosition(body, origin);
    MdtBodySetPosition(body, (MeReal)pos[0], (MeReal)pos[1], (MeReal)pos[2]);
    MdtBodySetQuaternion(body, (MeReal)quat[0], (MeReal)quat[1], (MeReal)quat[2], (MeReal)quat[3]);
    return m;
}

int bench_karma_contact_count(MstUniverseID u) { return MstBridgeGetLastContactCount(MstUniverseGetBridge(u)); }

void bench_karma_read(MdtBodyID *bodies, int count, double (*pos)[3], double (*quat)[4])
{
    for (int i = 0; i < count; i++) {
        if (!bodies[i])
            continue;
        MeVector3 p;
        MeVector4 q;
        MdtBodyGetPosition(bodies[i], p);
        MdtBodyGetQuaternion(bodies[i], q);
        for (int k = 0; k < 3; k++)
            pos[i][k] = p[k];
        for (int k = 0; k < 4; k++)
            quat[i][k] = q[k];
    }
}
