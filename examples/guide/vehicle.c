/* vehicle.c -- how-to "Vehicles": a 100 kg box of a car on four 10 kg ball wheels, each joined to the
 * chassis by a car wheel joint (suspension along the vertical, a hinge for rolling). The rear
 * wheels' motors turn at 10 rad/s; the car drives off and settles at the speed that rolling gives,
 * wheel speed times radius. */
#include <math.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

int main(void)
{
    const MeReal radius = 0.3, spin = 10; /* wheel radius (m) and the motors' target (rad/s) */
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 30; /* bodies of 10 to 100 kg */
    MstUniverseID universe = MstUniverseCreate(&sizes);
    MdtWorldID world = MstUniverseGetWorld(universe);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MstBridgeID bridge = MstUniverseGetBridge(universe);
    MdtWorldSetGravity(world, 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);
    /* Tyres grip: Coulomb friction with mu = 1 everywhere. */
    const MstMaterialID material = MstBridgeGetDefaultMaterial();
    MdtContactParamsID p = MstBridgeGetContactParams(bridge, material, material);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, 1);

    /* The chassis: 2 m long (along x), 0.4 m high, 1 m wide, its centre 0.6 m up. */
    McdModelID chassisModel = MstModelAndBodyCreate(universe, McdBoxCreate(collision, 2, 0.4, 1), 125);
    MdtBodyID chassis = McdModelGetBody(chassisModel);
    MdtBodySetPosition(chassis, 0, 0.6, 0);

    MdtCarWheelID joints[4];
    for (int k = 0; k < 4; k++) {
        const MeReal x = k < 2 ? 0.7f : -0.7f, z = k % 2 ? 0.6f : -0.6f; /* wheels 0, 1 front; 2, 3 rear */
        McdModelID wheelModel = MstModelAndBodyCreate(universe, McdSphereCreate(collision, radius), 88);
        MdtBodyID wheel = McdModelGetBody(wheelModel);
        MdtBodySetPosition(wheel, x, radius, z);
        McdSpaceDisablePair(chassisModel, wheelModel); /* the wheel turns inside the wheel arch */
        /* Body 0 the chassis, body 1 the wheel; the joint at the wheel's centre. The suspension slides
         * along the steering axis (up), the wheel rolls about the hinge axis (across the car). */
        MdtCarWheelID j = joints[k] = MdtCarWheelCreate(world);
        MdtCarWheelSetBodies(j, chassis, wheel);
        MdtCarWheelSetPosition(j, x, radius, z);
        MdtCarWheelSetSteeringAndHingeAxes(j, 0, 1, 0, 0, 0, 1);
        MdtCarWheelSetSteeringLock(j, METRUE); /* drive straight */
        /* Spring 5000 N/m, damper 300 N s/m, 0.1 m of travel either way. */
        MdtCarWheelSetSuspension(j, 5000, 300, 0, -0.1f, 0.1f, 0);
        if (k >= 2) /* rear-wheel drive; a positive spin about +z rolls the car towards -x */
            MdtCarWheelSetHingeLimitedForceMotor(j, spin, 100);
        MdtCarWheelEnable(j);
    }

    for (int second = 1; second <= 6; second++) {
        for (int step = 0; step < 60; step++)
            MstUniverseStep(universe, 1.0 / 60);
        MeVector3 v, position;
        MdtBodyGetLinearVelocity(chassis, v);
        MdtBodyGetPosition(chassis, position);
        if (second % 2 == 0)
            printf("t = %d s: speed %.2f m/s, %.1f m driven, springs compressed %.0f mm\n", second,
                   sqrt((double)(v[0] * v[0] + v[2] * v[2])), -(double)position[0],
                   -1000 * (double)MdtCarWheelGetSuspensionHeight(joints[2]));
    }
    printf("rolling without slipping: wheel speed x radius = %.2f m/s\n", (double)(spin * radius));
    printf("a quarter of the chassis on a 5000 N/m spring: 25 kg x 9.81 / 5000 = %.0f mm\n", 1000 * 25 * 9.81 / 5000);
    MstUniverseDestroy(universe);
    return 0;
}
