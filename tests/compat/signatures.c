/*
  signatures.c -- functions that Karma 1.2 programs call keep 1.2's signatures (issue 14, point 3).

  Each function is assigned to a pointer of the type Karma 1.2 declared it with. A C++ compiler
  refuses the program if a signature departs (C compilers only warn, which -Wall prints). These
  are the functions whose 1.2 calls would otherwise compile and misbehave: the relative
  position-orientation joint's attachment setters take the body index last in 1.2. The program
  also makes the calls as 1.2 programs do and checks that the joint holds the body where the
  attachment says.
*/
#include "Mdt.h"
#include "compat_check.h"

typedef void (MEAPI *RPROPositionFn)(const MdtRPROJointID j, const MeReal x, const MeReal y,
                                     const MeReal z, const unsigned int bodyindex);
typedef void (MEAPI *RPROQuaternionFn)(const MdtRPROJointID j, const MeReal q0, const MeReal q1,
                                       const MeReal q2, const MeReal q3, const unsigned int bodyindex);

int MEAPI_CDECL main(int argc, const char **argv)
{
    RPROPositionFn setPosition = MdtRPROJointSetAttachmentPosition;
    RPROQuaternionFn setQuaternion = MdtRPROJointSetAttachmentQuaternion;
    MdtWorldID world;
    MdtBodyID body;
    MdtRPROJointID joint;
    MeVector3 p;
    int i;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetAutoDisable(world, 0);
    MdtWorldSetGravity(world, 0, -(MeReal)9.8, 0);
    body = MdtBodyCreate(world);
    MdtBodySetPosition(body, 0, 2, 0);
    MdtBodyEnable(body);

    /* The joint's frame sits 1 m above the body's centre (body 0's frame) and at the world's
       (0, 3, 0) (body 1, the world): the body should stay at (0, 2, 0). */
    joint = MdtRPROJointCreate(world);
    MdtRPROJointSetBodies(joint, body, 0);
    setPosition(joint, 0, 1, 0, 0);
    setPosition(joint, 0, 3, 0, 1);
    setQuaternion(joint, 1, 0, 0, 0, 0);
    setQuaternion(joint, 1, 0, 0, 0, 1);
    MdtRPROJointEnable(joint);

    for (i = 0; i < 100; i++)
        MdtWorldStep(world, (MeReal)0.01);
    MdtBodyGetPosition(body, p);
    compatNear("the joint holds the body's height (m)", p[1], 2, 0.01);
    compatNear("and its sideways position (m)", p[0] * p[0] + p[2] * p[2], 0, 0.0001);

    MdtWorldDestroy(world);
    return compatExit("signatures");
}
