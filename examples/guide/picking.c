/* picking.c -- how-to "Picking an object": a line from the camera finds the box under the cursor, and
 * a spring made by hand (a force at the picked point, pulling it towards a target) lifts and carries
 * it. The box ends hanging from the picked point, which sags below the target by m g / k. */
#include <math.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

int main(void)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID universe = MstUniverseCreate(&sizes);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MdtWorldSetGravity(MstUniverseGetWorld(universe), 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);
    McdModelID box = MstModelAndBodyCreate(universe, McdBoxCreate(collision, 0.5, 0.5, 0.5), 8); /* 1 kg */
    MdtBodyID body = McdModelGetBody(box);
    MdtBodySetPosition(body, 0, 0.25, 0);
    for (int step = 0; step < 60; step++) /* a second: the box settles and falls asleep */
        MstUniverseStep(universe, 1.0 / 60);

    /* The cursor's line: from the camera at (0, 2, 5) through the scene, 10 m long. */
    MeVector3 eye = {0, 2, 5}, through = {0, 0.25f, 0}, far;
    for (int k = 0; k < 3; k++)
        far[k] = eye[k] + 10 * (through[k] - eye[k]) / (MeReal)sqrt(5 * 5 + 1.75 * 1.75);
    /* Between steps a universe keeps its space open for changes; a query needs it closed. */
    McdSpaceID space = MstUniverseGetSpace(universe);
    McdSpaceEndChanges(space);
    McdLineSegIntersectResult hit;
    int found = McdSpaceGetLineSegFirstIntersection(space, eye, far, &hit);
    McdSpaceBeginChanges(space);
    if (!found || hit.model != box) {
        printf("missed the box\n");
        return 1;
    }
    printf("picked the box at (%.2f, %.2f, %.2f), %.2f m from the camera\n", (double)hit.position[0],
           (double)hit.position[1], (double)hit.position[2], (double)hit.distance);

    /* The picked point in the box's own frame: it moves with the box. */
    MeVector3 local, target = {1, 1.5, 0};
    MdtConvertPositionVector(NULL, hit.position, body, local);
    const MeReal k = 200, c = 20; /* the hand's spring: 200 N/m, damped by 20 N s/m */
    MdtBodyEnable(body);          /* wake the sleeping box: forces alone do not */
    MdtBodySetAngularVelocityDamping(body, 0.2); /* and calm its swing about the picked point */
    for (int step = 0; step < 5 * 60; step++) {
        MeVector3 point, v;
        MdtConvertPositionVector(body, local, NULL, point);
        MdtBodyGetVelocityAtPoint(body, point, v);
        MdtBodyAddForceAtPosition(body, k * (target[0] - point[0]) - c * v[0], k * (target[1] - point[1]) - c * v[1],
                                  k * (target[2] - point[2]) - c * v[2], point[0], point[1], point[2]);
        MstUniverseStep(universe, 1.0 / 60);
    }
    MeVector3 point;
    MdtConvertPositionVector(body, local, NULL, point);
    printf("after 5 s the picked point is at (%.2f, %.2f, %.2f): %.3f m below the target (%.0f, %.1f, %.0f)\n",
           (double)point[0], (double)point[1], (double)point[2], (double)(target[1] - point[1]),
           (double)target[0], (double)target[1], (double)target[2]);
    printf("a spring of k = %.0f N/m holding 1 kg sags m g / k = %.3f m\n", (double)k, 9.81 / (double)k);
    MstUniverseDestroy(universe);
    return 0;
}
