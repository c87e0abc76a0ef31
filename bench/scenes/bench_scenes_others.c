/* bench_scenes_others.c -- the scene set of others' making (issue 17): 3-D versions of Box2D v3's
 * benchmark scenes (shared/benchmarks.c: large pyramid, many pyramids, joint grid, rain, smash,
 * spinner, tumbler) and of Jolt's performance scenes (PerformanceTest: pyramid, ragdolls), defined once
 * for Karma, ODE and Bullet. Parameters (sizes, densities, speeds, joint types) are the sources';
 * counts are scaled down for a 2-core machine. Box2D's plane (x, y) is this bench's (z, y), y up,
 * with depth along x, as in the bench's own pyramids; a 2-D revolute joint is a hinge about x.
 * Bodies that rest start exactly touching. What each scene maps and approximates:
 * bench/scenes/README.md. */
#include "bench_scenes_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const double kPi = 3.14159265358979323846;
static const double kAxisX[3] = {1, 0, 0};

/* Mass of a uniform solid of `density` (kg/m³): box half-extents a, b, c; sphere radius a; capsule
 * radius a and half-length b. */
static double solid_mass(BenchShape shape, double a, double b, double c, double density)
{
    switch (shape) {
    case BENCH_SPHERE:
        return density * 4.0 / 3.0 * kPi * a * a * a;
    case BENCH_CAPSULE:
        return density * (kPi * a * a * 2 * b + 4.0 / 3.0 * kPi * a * a * a);
    case BENCH_BOX:
    default:
        return density * 8 * a * b * c;
    }
}

/* Size: add_body's parameters with a density in place of the mass. */
static int add_solid(BenchScene *s, BenchShape shape, double a, double b, double c, double density,
                     const double pos[3], const double quat[4], int fixed)
{
    return add_body(s, shape, a, b, c, fixed ? 0 : solid_mass(shape, a, b, c, density), pos, quat, fixed);
}

/* A hinge of body `b` to the world about `axis` through `anchor`, whose motor turns the body at
 * `speed` rad/s with at most `torque` N m. */
static void add_motor(BenchScene *s, int b, const double anchor[3], const double axis[3], double speed,
                      double torque)
{
    add_joint(s, BENCH_HINGE, b, -1, anchor, axis, 1, 0);
    BenchJoint *j = &s->joints[s->jointCount - 1];
    j->motor = 1;
    j->motorSpeed = speed;
    j->motorTorque = torque;
}

static void stack_quality(BenchScene *s, double fallDistance)
{
    s->quality = BENCH_Q_MAX_DRIFT;
    s->qualityName = "max_drift_m";
    s->fallDistance = fallDistance;
}

/* Box2D's large pyramid: b2MakeSquare(0.5) boxes (unit boxes), density 1, touching, base 100 (5,050
 * boxes; 40 here: 820). Box2D's ground box becomes the plane. */
BenchScene *BenchSceneB2Pyramid(int base)
{
    if (base < 1)
        return NULL;
    int count = base * (base + 1) / 2;
    BenchScene *s = scene_new("b2pyramid", base, 40, count, 0);
    if (!s)
        return NULL;
    for (int row = 0; row < base; row++)
        for (int j = row; j < base; j++) {
            double p[3] = {0, 0.5 + row, 0.5 * (row + 1) + (j - row) - 0.5 * base};
            add_solid(s, BENCH_BOX, 0.5, 0.5, 0.5, 1.0, p, kIdentity, 0);
        }
    snprintf(s->description, sizeof s->description,
             "Box2D's large pyramid: %d touching unit boxes (base %d) one deep, on the ground, 10 s", count, base);
    stack_quality(s, BENCH_FALL_DISTANCE);
    scene_finish(s);
    return s;
}

/* Box2D's many pyramids: 20 x 20 touching pyramids of base 10 (unit boxes) on 20 shelves, 1 m apart
 * along a shelf (22,000 boxes). Here `count` pyramids on the ground on a grid: 11 m apart along z (Box2D's
 * spacing) and 2 m apart along x (the shelves, brought down to the ground one behind the other). */
BenchScene *BenchSceneB2Pyramids(int count)
{
    if (count < 1)
        return NULL;
    const int base = 10, per = base * (base + 1) / 2;
    int columns = 1;
    while (columns * columns < count)
        columns++;
    int rows = (count + columns - 1) / columns;
    BenchScene *s = scene_new("b2pyramids", count, 12, count * per, 0);
    if (!s)
        return NULL;
    for (int k = 0; k < count; k++) {
        double z0 = ((k % columns) - 0.5 * (columns - 1)) * (base + 1), x0 = ((k / columns) - 0.5 * (rows - 1)) * 2.0;
        for (int row = 0; row < base; row++) {
            int n = base - row;
            for (int i = 0; i < n; i++) {
                double p[3] = {x0, 0.5 + row, z0 + (i - 0.5 * (n - 1))};
                add_solid(s, BENCH_BOX, 0.5, 0.5, 0.5, 1.0, p, kIdentity, 0);
            }
        }
    }
    snprintf(s->description, sizeof s->description,
             "Box2D's many pyramids: %d touching pyramids of 55 unit boxes on the ground, 10 s", count);
    stack_quality(s, BENCH_FALL_DISTANCE);
    scene_finish(s);
    return s;
}

/* Box2D's joint grid: 100 x 100 circles (r 0.4, density 1) 1 m apart, revolute joints to the right and
 * lower neighbours, seven bodies in the middle of the top row static, no ground, no sleeping, grid
 * bodies not colliding (a filter). Here `side` x `side` spheres (r 0.4, density 1) in the y-z plane on
 * hinges about x; the seven static bodies are left out and their joints go to the world at the same
 * anchors. Spheres 1 m apart cannot touch their unjoined neighbours (1.41 m) while the grid holds. */
BenchScene *BenchSceneB2JointGrid(int side)
{
    if (side < 1)
        return NULL;
    int *index = malloc(sizeof *index * (size_t)side * (size_t)side);
    BenchScene *s = index ? scene_new("b2jointgrid", side, 20, side * side, 2 * side * side) : NULL;
    if (!s) {
        free(index);
        return NULL;
    }
    s->hasGround = 0;
    for (int k = 0; k < side; k++)     /* columns along z */
        for (int i = 0; i < side; i++) { /* rows downwards */
            int fixed = i == 0 && k >= side / 2 - 3 && k <= side / 2 + 3;
            double p[3] = {0, side - i, k - 0.5 * (side - 1)};
            index[k * side + i] = fixed ? -1 : add_solid(s, BENCH_SPHERE, 0.4, 0, 0, 1.0, p, kIdentity, 0);
            /* joints to the body above and to the body on the left, at the midpoints */
            for (int n = 0; n < 2; n++) {
                if ((n == 0 && i == 0) || (n == 1 && k == 0))
                    continue;
                int other = n == 0 ? index[k * side + i - 1] : index[(k - 1) * side + i];
                int self = index[k * side + i];
                if (self < 0 && other < 0)
                    continue; /* static to static */
                double anchor[3] = {0, p[1] + (n == 0 ? 0.5 : 0), p[2] - (n == 1 ? 0.5 : 0)};
                if (self < 0)
                    add_joint(s, BENCH_HINGE, other, -1, anchor, kAxisX, 1, 0);
                else
                    add_joint(s, BENCH_HINGE, self, other, anchor, kAxisX, 1, 0);
            }
        }
    free(index);
    snprintf(s->description, sizeof s->description,
             "Box2D's joint grid: %d x %d spheres (r 0.4 m) on hinges, hung from the world by the top row's middle, 10 s",
             side, side);
    s->quality = BENCH_Q_JOINT_ERROR;
    s->qualityName = "joint_err_m";
    scene_finish(s);
    return s;
}

/* Box2D's rain: groups of five humans (11 bodies, capsules on revolute joints) created every 8 steps in
 * 40 columns on 5 levels 45 m apart, each dropping 40 m onto a row of small boxes, the oldest destroyed
 * once 1,000 humans exist. The harness keeps a fixed set of bodies, so here `count` ragdolls (the
 * bench's 11-body ragdoll) stand in columns of five on a 3 m grid, each column's ragdolls 10 m above one
 * another (lowest points 0.5 to 40.5 m up), so that they land one after another over the first 3 s. */
BenchScene *BenchSceneB2Rain(int count)
{
    if (count < 1)
        return NULL;
    const int perColumn = 5;
    int columns = (count + perColumn - 1) / perColumn, side = 1;
    while (side * side < columns)
        side++;
    BenchScene *s = scene_new("b2rain", count, 45, 11 * count, 10 * count);
    if (!s)
        return NULL;
    for (int k = 0; k < count; k++) {
        int c = k / perColumn, level = k % perColumn;
        double q[4];
        ragdoll_tilt(q, k);
        double place[3] = {((c / side) - 0.5 * (side - 1)) * 3.0, 0, ((c % side) - 0.5 * (side - 1)) * 3.0};
        add_ragdoll(s, q, place, 0.5 + 10.0 * level);
    }
    snprintf(s->description, sizeof s->description,
             "Box2D's rain: %d ragdolls in columns of 5 dropped from 0.5 to 40.5 m onto the ground, 10 s", count);
    s->quality = BENCH_Q_JOINT_ERROR;
    s->qualityName = "joint_err_m";
    scene_finish(s);
    return s;
}

/* Box2D's smash: no gravity; a box of 8 m (density 8) at 40 m/s into a touching block of 120 x 80
 * boxes of 0.4 m (density 1, created asleep). Here the block is `columns` (along z, the direction of
 * travel) x 12 (y) x 3 (x) boxes of 0.4 m, and the projectile 8 m x 8 m x the block's depth. */
BenchScene *BenchSceneB2Smash(int columns)
{
    if (columns < 1)
        return NULL;
    const int rows = 12, depth = 3;
    const double d = 0.4;
    BenchScene *s = scene_new("b2smash", columns, 12, columns * rows * depth + 1, 0);
    if (!s)
        return NULL;
    s->hasGround = 0;
    s->gravity[1] = 0;
    const double pp[3] = {0, 0, -20};
    int projectile = add_solid(s, BENCH_BOX, 0.5 * depth * d, 4, 4, 8.0, pp, kIdentity, 0);
    s->bodies[projectile].vel[2] = 40;
    for (int i = 0; i < columns; i++)
        for (int j = 0; j < rows; j++)
            for (int k = 0; k < depth; k++) {
                double p[3] = {(k - 0.5 * (depth - 1)) * d, (j - 0.5 * rows) * d, 30 + i * d};
                add_solid(s, BENCH_BOX, 0.5 * d, 0.5 * d, 0.5 * d, 1.0, p, kIdentity, 0);
            }
    snprintf(s->description, sizeof s->description,
             "Box2D's smash: no gravity; an 8 m box at 40 m/s into a touching block of %d boxes of 0.4 m, 10 s",
             columns * rows * depth);
    s->quality = BENCH_Q_COM_DRIFT;
    s->qualityName = "com_drift_m";
    scene_finish(s);
    return s;
}

/* Box2D's spinner: a static ring (a chain loop of radius 40, friction 0.1), a bar of 0.8 m x 40 m (a
 * rounded box, density 1, friction 0) on a revolute joint 20 m below the ring's centre driven at 5 rad/s
 * with unbounded torque, and 6,076 capsules (r 0.25, 1 m long), circles (r 0.35) and squares (0.7 m),
 * density 0.25, friction 0.1, restitution 0.1, overlapping on a 0.5 m grid at the start. Here the ring
 * is scaled by 1/4 (radius 10: 32 static boxes 1 m thick around x, closed by two static end plates 2.4 m
 * apart), the bar is 9 m x 0.8 m x 2.3 m on a motorised hinge about x 5 m below the centre, and up to
 * `count` capsules, spheres and boxes of Box2D's sizes and density fill the ring's lower half on a grid
 * where none overlaps (1.05 m along z, 0.75 m along y and x, three deep), the bar's sweep left clear. */
BenchScene *BenchSceneB2Spinner(int count)
{
    if (count < 1)
        return NULL;
    const int segments = 32;
    const double radius = 10, centre = 10, halfDepth = 1.2, reach = 0.62;
    BenchScene *s = scene_new("b2spinner", count, 450, count + segments + 3, 1);
    if (!s)
        return NULL;
    s->hasGround = 0;
    s->friction = 0.1;
    for (int k = 0; k < segments; k++) {
        double phi = 2 * kPi * k / segments, q[4];
        BenchQuatFromAxisAngle(q, kAxisX, phi);
        double p[3] = {0, centre + (radius + 0.5) * cos(phi), (radius + 0.5) * sin(phi)};
        add_solid(s, BENCH_BOX, halfDepth + 1, 0.5, (radius + 1) * tan(kPi / segments), 0, p, q, 1);
    }
    for (int side = -1; side <= 1; side += 2) {
        double p[3] = {side * (halfDepth + 0.5), centre, 0};
        add_solid(s, BENCH_BOX, 0.5, radius + 1, radius + 1, 0, p, kIdentity, 1);
    }
    const double pivot[3] = {0, centre - 0.5 * radius, 0};
    int bar = add_solid(s, BENCH_BOX, halfDepth - 0.05, 4.5, 0.4, 1.0, pivot, kIdentity, 0);
    add_motor(s, bar, pivot, kAxisX, 5.0, 1e8);
    int made = 0;
    for (int row = 0; made < count; row++) {
        double y = 1.0 + 0.75 * row;
        if (y > centre + 2)
            break;
        for (int m = 0; made < count; m++) {
            double z = 1.0 + 1.05 * m;
            if (hypot(y - centre, z) + reach > radius - 0.1)
                break;
            for (int sign = -1; sign <= 1 && made < count; sign += 2)
                for (int layer = -1; layer <= 1 && made < count; layer++) {
                    double p[3] = {0.75 * layer, y, sign * z};
                    switch (made % 3) {
                    case 0: /* Box2D's capsule lies along its x: here along z, unrotated */
                        add_solid(s, BENCH_CAPSULE, 0.25, 0.25, 0, 0.25, p, kIdentity, 0);
                        break;
                    case 1:
                        add_solid(s, BENCH_SPHERE, 0.35, 0, 0, 0.25, p, kIdentity, 0);
                        break;
                    default:
                        add_solid(s, BENCH_BOX, 0.35, 0.35, 0.35, 0.25, p, kIdentity, 0);
                        break;
                    }
                    made++;
                }
        }
    }
    snprintf(s->description, sizeof s->description,
             "Box2D's spinner: %d capsules spheres and boxes in a static ring stirred by a bar at 5 rad/s, 10 s",
             made);
    s->quality = BENCH_Q_ESCAPED;
    s->qualityName = "escaped";
    s->container[0][0] = -halfDepth;
    s->container[1][0] = halfDepth;
    s->container[0][1] = centre - radius;
    s->container[1][1] = centre + radius;
    s->container[0][2] = -radius;
    s->container[1][2] = radius;
    scene_finish(s);
    return s;
}

/* Box2D's tumbler: a dynamic square box of four walls (20 m inside, 1 m thick, density 50) on a
 * revolute joint to the world driven at 25 degrees/s (torque up to 1e8 N m), and 45 x 45 boxes of
 * 0.25 m (density 1) on a 0.4 m grid inside; no ground. The harness has no compound bodies, so here the
 * drum is six bodies, each on its own motorised hinge about x through the drum's centre (same speed and
 * torque): four walls (6 m inside, 0.5 m thick, 2 m deep, density 50) and two end plates, 0.05 m
 * apart so that they never touch one another; inside, `side` x `side` x 4 boxes of 0.25 m on Box2D's
 * 0.4 m grid. */
BenchScene *BenchSceneB2Tumbler(int side)
{
    if (side < 1 || side > 14)
        return NULL;
    const double a = 3, c = 1, t = 0.5, g = 0.05, yc = 5, density = 50, speed = 25 * kPi / 180, torque = 1e8;
    const int depth = 4;
    BenchScene *s = scene_new("b2tumbler", side, 10, side * side * depth + 6, 6);
    if (!s)
        return NULL;
    s->hasGround = 0;
    const double axle[3] = {0, yc, 0};
    for (int sign = -1; sign <= 1; sign += 2) {
        double pz[3] = {0, yc, sign * (a + 0.5 * t)}, py[3] = {0, yc + sign * (a + 0.5 * t), 0},
               px[3] = {sign * (c + g + 0.5 * t), yc, 0};
        add_motor(s, add_solid(s, BENCH_BOX, c, a + t, 0.5 * t, density, pz, kIdentity, 0), axle, kAxisX, speed, torque);
        add_motor(s, add_solid(s, BENCH_BOX, c, 0.5 * t, a - g, density, py, kIdentity, 0), axle, kAxisX, speed, torque);
        add_motor(s, add_solid(s, BENCH_BOX, 0.5 * t, a + t, a + t, density, px, kIdentity, 0), axle, kAxisX, speed,
                  torque);
    }
    for (int i = 0; i < side; i++)
        for (int j = 0; j < side; j++)
            for (int k = 0; k < depth; k++) {
                double p[3] = {(k - 0.5 * (depth - 1)) * 0.4, yc + (i - 0.5 * (side - 1)) * 0.4,
                               (j - 0.5 * (side - 1)) * 0.4};
                add_solid(s, BENCH_BOX, 0.125, 0.125, 0.125, 1.0, p, kIdentity, 0);
            }
    snprintf(s->description, sizeof s->description,
             "Box2D's tumbler: %d boxes of 0.25 m in a drum of six walls turning at 25 degrees/s, 10 s",
             side * side * depth);
    s->quality = BENCH_Q_ESCAPED;
    s->qualityName = "escaped";
    double r = (a + t) * sqrt(2.0);
    s->container[0][0] = -(c + g);
    s->container[1][0] = c + g;
    s->container[0][1] = yc - r;
    s->container[1][1] = yc + r;
    s->container[0][2] = -r;
    s->container[1][2] = r;
    scene_finish(s);
    return s;
}

/* Jolt's pyramid (PerformanceTest PyramidScene): boxes of 2 m (density 1000: 8,000 kg), 15 layers, layer
 * i (15 - i)² boxes offset by half a box on odd layers (each box on four), 0.5 m dropped between layers,
 * no sleeping, a static floor box. Here `height` layers (10: 385 boxes), touching (no drop), on the
 * plane, Jolt's default friction 0.2. */
BenchScene *BenchSceneJoltPyramid(int height)
{
    if (height < 1)
        return NULL;
    int count = 0;
    for (int i = 0; i < height; i++)
        count += (height - i) * (height - i);
    BenchScene *s = scene_new("joltpyramid", height, 10, count, 0);
    if (!s)
        return NULL;
    s->friction = 0.2;
    for (int i = 0; i < height; i++)
        for (int j = i / 2; j < height - (i + 1) / 2; j++)
            for (int k = i / 2; k < height - (i + 1) / 2; k++) {
                double p[3] = {-height + 2.0 * j + (i & 1), 1.0 + 2.0 * i, -height + 2.0 * k + (i & 1)};
                add_solid(s, BENCH_BOX, 1, 1, 1, 1000, p, kIdentity, 0);
            }
    snprintf(s->description, sizeof s->description,
             "Jolt's pyramid: %d touching boxes of 2 m (8 t) in %d layers on the ground, 10 s", count, height);
    stack_quality(s, 1.0); /* half an edge of a 2 m box */
    scene_finish(s);
    return s;
}

/* Jolt's ragdolls (PerformanceTest RagdollScene): 4 x 4 piles, 4 m apart, of 10 ragdolls (Jolt's human:
 * 19 bodies on swing-twist constraints, motors driving to a lying pose) 0.6 m above one another, each
 * turned by 36 degrees more about the vertical, dropped on a terrain mesh. Here `count` of the bench's
 * 11-body ragdolls (no motors) lying face down, in piles of ten on a 4 m grid, their lowest points 0.5,
 * 1.1, 1.7 ... m up, on the plane, Jolt's default friction 0.2. */
BenchScene *BenchSceneJoltRagdolls(int count)
{
    if (count < 1)
        return NULL;
    const int pileSize = 10;
    int piles = (count + pileSize - 1) / pileSize, side = 1;
    while (side * side < piles)
        side++;
    BenchScene *s = scene_new("joltragdolls", count, 40, 11 * count, 10 * count);
    if (!s)
        return NULL;
    s->friction = 0.2;
    for (int k = 0; k < count; k++) {
        int pile = k / pileSize, i = k % pileSize;
        double qYaw[4], qLie[4], q[4];
        BenchQuatFromAxisAngle(qYaw, kAxisY, 2 * kPi * i / pileSize);
        BenchQuatFromAxisAngle(qLie, kAxisZ, 0.5 * kPi);
        BenchQuatMultiply(q, qYaw, qLie);
        double place[3] = {((pile % side) - 0.5 * (side - 1)) * 4.0, 0, ((pile / side) - 0.5 * (side - 1)) * 4.0};
        add_ragdoll(s, q, place, 0.5 + 0.6 * i);
    }
    snprintf(s->description, sizeof s->description,
             "Jolt's ragdolls: %d ragdolls lying in piles of 10 (0.6 m apart) dropped on the ground, 10 s", count);
    s->quality = BENCH_Q_JOINT_ERROR;
    s->qualityName = "joint_err_m";
    scene_finish(s);
    return s;
}

BenchScene *BenchSceneOthersCreate(const char *name)
{
    int n;
    /* longer prefixes first: "b2pyramids" before "b2pyramid" */
    if ((n = parse_count(name, "b2pyramids", 12)) > 0)
        return BenchSceneB2Pyramids(n);
    if ((n = parse_count(name, "b2pyramid", 40)) > 0)
        return BenchSceneB2Pyramid(n);
    if ((n = parse_count(name, "b2jointgrid", 20)) > 0)
        return BenchSceneB2JointGrid(n);
    if ((n = parse_count(name, "b2rain", 45)) > 0)
        return BenchSceneB2Rain(n);
    if ((n = parse_count(name, "b2smash", 12)) > 0)
        return BenchSceneB2Smash(n);
    if ((n = parse_count(name, "b2spinner", 450)) > 0)
        return BenchSceneB2Spinner(n);
    if ((n = parse_count(name, "b2tumbler", 10)) > 0)
        return BenchSceneB2Tumbler(n);
    if ((n = parse_count(name, "joltpyramid", 10)) > 0)
        return BenchSceneJoltPyramid(n);
    if ((n = parse_count(name, "joltragdolls", 40)) > 0)
        return BenchSceneJoltRagdolls(n);
    return NULL;
}
