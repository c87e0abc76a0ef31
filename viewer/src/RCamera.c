/* RCamera.c -- Karma's orbit camera: a look-at point, a distance, a rotation θ about y (from +z, in
 * the x–z plane) and an elevation φ; the matrices are recomputed by RCameraUpdate. */
#include <math.h>
#include <string.h>

#include "RInternal.h"

#define R_PI 3.14159265358979323846
/** Closest the camera comes to the look-at point (m), as Karma. */
#define R_MIN_DISTANCE 0.01
/** The elevation stays this far from straight up or down, where the up vector is undefined. */
#define R_MAX_ELEVATION (R_PI / 2 - 0.001)

static double clampElevation(double phi)
{
    return phi > R_MAX_ELEVATION ? R_MAX_ELEVATION : phi < -R_MAX_ELEVATION ? -R_MAX_ELEVATION : phi;
}

void RCameraSetDefaults(RRender *rc)
{
    rc->m_CameraLookAt[0] = 0, rc->m_CameraLookAt[1] = 0, rc->m_CameraLookAt[2] = 1;
    rc->m_CameraDist = 15;
    rc->m_CameraTheta = 0;
    rc->m_CameraPhi = 0;
    rc->m_Fov = (AcmeReal)(R_PI / 6);
    RCameraUpdate(rc);
}

void MEAPI RCameraGetPosition(RRender *rc, AcmeVector3 pos)
{
    double d = rc->m_CameraDist, t = rc->m_CameraTheta, p = rc->m_CameraPhi;
    pos[0] = (AcmeReal)(rc->m_CameraLookAt[0] + d * sin(t) * cos(p));
    pos[1] = (AcmeReal)(rc->m_CameraLookAt[1] + d * sin(p));
    pos[2] = (AcmeReal)(rc->m_CameraLookAt[2] + d * cos(t) * cos(p));
}

/* Unit vectors of the eye frame in the world: right, up, and forward (towards the look-at point). */
static void eyeFrame(RRender *rc, double r[3], double u[3], double f[3])
{
    double t = rc->m_CameraTheta, p = rc->m_CameraPhi;
    f[0] = -sin(t) * cos(p), f[1] = -sin(p), f[2] = -cos(t) * cos(p);
    r[0] = cos(t), r[1] = 0, r[2] = -sin(t); /* f × (0, 1, 0), normalised */
    u[0] = r[1] * f[2] - r[2] * f[1], u[1] = r[2] * f[0] - r[0] * f[2], u[2] = r[0] * f[1] - r[1] * f[0];
}

/* The projection: perspective with half-angle m_Fov, or (orthographic) a parallel box whose half
 * height is what the perspective shows at the look-at point, so switching keeps that plane's scale. */
static void updateProjection(RRender *rc)
{
    double aspect = rc->m_AspectRatio > 0 ? rc->m_AspectRatio : 640.0 / 448.0;
    double k = 1 / tan(rc->m_Fov), n = NEARZ, fz = FARZ;
    MeReal(*p)[4] = rc->m_ProjMatrix;
    memset(p, 0, sizeof rc->m_ProjMatrix);
    if (rc->m_private && rc->m_private->orthographic) {
        double h = rc->m_CameraDist / k;
        p[0][0] = (MeReal)(1 / (h * aspect));
        p[1][1] = (MeReal)(1 / h);
        p[2][2] = (MeReal)(2 / (n - fz));
        p[3][2] = (MeReal)((fz + n) / (n - fz));
        p[3][3] = 1;
        return;
    }
    p[0][0] = (MeReal)(k / aspect);
    p[1][1] = (MeReal)k;
    p[2][2] = (MeReal)((fz + n) / (n - fz));
    p[2][3] = -1;
    p[3][2] = (MeReal)(2 * fz * n / (n - fz));
}

void MEAPI RCameraUpdate(RRender *rc)
{
    if (!rc)
        return;
    if (rc->m_CameraDist < R_MIN_DISTANCE)
        rc->m_CameraDist = (AcmeReal)R_MIN_DISTANCE;
    rc->m_CameraPhi = (AcmeReal)clampElevation(rc->m_CameraPhi);
    double r[3], u[3], f[3];
    AcmeVector3 pos;
    eyeFrame(rc, r, u, f);
    RCameraGetPosition(rc, pos);
    MeReal(*m)[4] = rc->m_CamMatrix;
    memset(m, 0, sizeof rc->m_CamMatrix);
    double rp = 0, up = 0, fp = 0;
    for (int i = 0; i < 3; i++) {
        m[i][0] = (MeReal)r[i];
        m[i][1] = (MeReal)u[i];
        m[i][2] = (MeReal)-f[i];
        rp += r[i] * pos[i], up += u[i] * pos[i], fp += f[i] * pos[i];
    }
    m[3][0] = (MeReal)-rp, m[3][1] = (MeReal)-up, m[3][2] = (MeReal)fp, m[3][3] = 1;

    updateProjection(rc);
}

void MEAPI RCameraSetView(RRender *rc, AcmeReal dist, AcmeReal theta, AcmeReal phi)
{
    if (!rc)
        return;
    if (!isfinite(dist) || !isfinite(theta) || !isfinite(phi)) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RCameraSetView", "distance and angles must be finite");
        return;
    }
    rc->m_CameraDist = dist, rc->m_CameraTheta = theta, rc->m_CameraPhi = phi;
    RCameraUpdate(rc);
}

void MEAPI RCameraSetLookAt(RRender *rc, const AcmeVector3 lookAt)
{
    if (!rc || !lookAt)
        return;
    for (int i = 0; i < 3; i++)
        rc->m_CameraLookAt[i] = lookAt[i];
    RCameraUpdate(rc);
}

void MEAPI RCameraGetLookAt(RRender *rc, AcmeVector3 camlookat)
{
    for (int i = 0; i < 3; i++)
        camlookat[i] = rc->m_CameraLookAt[i];
}

void MEAPI RCameraSetLookAtAndPosition(RRender *rc, const MeVector3 lookAt, const MeVector3 position)
{
    double d[3] = {position[0] - lookAt[0], position[1] - lookAt[1], position[2] - lookAt[2]};
    double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(l >= R_MIN_DISTANCE) || !isfinite(l)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RCameraSetLookAtAndPosition", "position and look-at must be apart and finite");
        return;
    }
    for (int i = 0; i < 3; i++)
        rc->m_CameraLookAt[i] = lookAt[i];
    rc->m_CameraDist = (AcmeReal)l;
    rc->m_CameraPhi = (AcmeReal)asin(d[1] / l);
    rc->m_CameraTheta = (AcmeReal)atan2(d[0], d[2]);
    RCameraUpdate(rc);
}

AcmeReal MEAPI RCameraGetDistance(RRender *rc)
{
    return rc->m_CameraDist;
}

AcmeReal MEAPI RCameraGetElevation(RRender *rc)
{
    return rc->m_CameraPhi;
}

AcmeReal MEAPI RCameraGetRotation(RRender *rc)
{
    return rc->m_CameraTheta;
}

void MEAPI RCameraSetElevation(RRender *rc, const MeReal elevation)
{
    rc->m_CameraPhi = elevation;
    RCameraUpdate(rc);
}

void MEAPI RCameraGetUp(RRender *rc, AcmeVector3 up)
{
    double r[3], u[3], f[3];
    eyeFrame(rc, r, u, f);
    for (int i = 0; i < 3; i++)
        up[i] = (AcmeReal)u[i];
}

void MEAPI RCameraGetMatrix(RRender *rc, MeMatrix4Ptr m)
{
    memcpy(m, rc->m_CamMatrix, sizeof rc->m_CamMatrix);
}

void MEAPI RCameraSetFov(RRender *rc, AcmeReal fov)
{
    if (!(fov > 0 && fov < R_PI / 2)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RCameraSetFov", "the half-angle must be in (0, pi/2) (got %g)", (double)fov);
        return;
    }
    rc->m_Fov = fov;
    RCameraUpdate(rc);
}

static void moveLookAt(RRender *rc, const double dir[3], double dist)
{
    for (int i = 0; i < 3; i++)
        rc->m_CameraLookAt[i] += (AcmeReal)(dir[i] * dist);
    RCameraUpdate(rc);
}

void MEAPI RCameraPanX(RRender *rc, AcmeReal dist)
{
    double r[3], u[3], f[3];
    eyeFrame(rc, r, u, f);
    moveLookAt(rc, r, dist);
}

void MEAPI RCameraPanY(RRender *rc, AcmeReal dist)
{
    static const double y[3] = {0, 1, 0};
    moveLookAt(rc, y, dist);
}

void MEAPI RCameraPanZ(RRender *rc, AcmeReal dist)
{
    double t = rc->m_CameraTheta, ground[3] = {-sin(t), 0, -cos(t)};
    moveLookAt(rc, ground, dist);
}

void MEAPI RCameraRotateAngle(RRender *rc, AcmeReal d_theta)
{
    rc->m_CameraTheta += d_theta;
    RCameraUpdate(rc);
}

void MEAPI RCameraRotateElevation(RRender *rc, AcmeReal d_phi)
{
    rc->m_CameraPhi += d_phi;
    RCameraUpdate(rc);
}

void MEAPI RCameraZoom(RRender *rc, AcmeReal dist)
{
    rc->m_CameraDist -= dist;
    RCameraUpdate(rc);
}

/* Set one of the orbit's values if finite (else report `who`), then recompute the matrices. */
static void setOrbitValue(RRender *rc, AcmeReal *value, MeReal to, const char *who)
{
    if (!isfinite(to)) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, who, "the value must be finite");
        return;
    }
    *value = to;
    RCameraUpdate(rc);
}

void MEAPI RCameraSetRotation(RRender *rc, const MeReal rotation)
{
    if (rc)
        setOrbitValue(rc, &rc->m_CameraTheta, rotation, "RCameraSetRotation");
}

void MEAPI RCameraSetOffset(RRender *rc, const MeReal offset)
{
    if (rc)
        setOrbitValue(rc, &rc->m_CameraDist, offset, "RCameraSetOffset");
}

void MEAPI RCameraGetLookDir(RRender *rc, AcmeVector3 dir)
{
    /* The eye looks down its −z: the matrix's third column, negated (row-vector convention). */
    for (int i = 0; i < 3; i++)
        dir[i] = -rc->m_CamMatrix[i][2];
}

void MEAPI RCameraSetMatrix(RRender *rc, MeMatrix4Ptr m)
{
    if (!rc || !m)
        return;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(m[i][j])) {
                R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RCameraSetMatrix", "the matrix must be finite");
                return;
            }
    memcpy(rc->m_CamMatrix, m, sizeof rc->m_CamMatrix);
}

void MEAPI RCameraSetOrthographic(RRender *rc, MeBool on)
{
    if (!rc || !rc->m_private)
        return;
    rc->m_private->orthographic = on ? 1 : 0;
    RCameraUpdate(rc);
}

MeBool MEAPI RCameraIsOrthographic(RRender *rc)
{
    return rc && rc->m_private && rc->m_private->orthographic;
}

void MEAPI RCameraSetPreset(RRender *rc, RCameraPreset preset)
{
    if (!rc)
        return;
    /* θ from +z in the x–z plane, φ elevation: front looks along −z, right along −x, top down −y. */
    static const double angles[6][2] = {
        {0, 0}, {R_PI, 0}, {-R_PI / 2, 0}, {R_PI / 2, 0}, {0, R_PI / 2}, {0, -R_PI / 2},
    };
    if ((int)preset < 0 || (int)preset >= 6) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RCameraSetPreset", "unknown preset %d", (int)preset);
        return;
    }
    rc->m_CameraTheta = (AcmeReal)angles[preset][0];
    rc->m_CameraPhi = (AcmeReal)angles[preset][1];
    RCameraUpdate(rc);
}

void MEAPI RCameraSetFrontView(RRender *rc) { RCameraSetPreset(rc, kRCameraFront); }
void MEAPI RCameraSetBackView(RRender *rc) { RCameraSetPreset(rc, kRCameraBack); }
void MEAPI RCameraSetLeftView(RRender *rc) { RCameraSetPreset(rc, kRCameraLeft); }
void MEAPI RCameraSetRightView(RRender *rc) { RCameraSetPreset(rc, kRCameraRight); }
void MEAPI RCameraSetTopView(RRender *rc) { RCameraSetPreset(rc, kRCameraTop); }
void MEAPI RCameraSetBottomView(RRender *rc) { RCameraSetPreset(rc, kRCameraBottom); }
void MEAPI RCameraSetOrthographicView(RRender *rc) { RCameraSetOrthographic(rc, METRUE); }
