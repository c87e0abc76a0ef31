/* RLight.c -- Karma's lights and their defaults: a 0.2 grey ambient light, directional light 1 on
 * (towards (0.86, 0.26, 0.43): ambient 0.7, diffuse 0.6, specular 0.5), directional light 2 and the
 * point light off (attenuation 1, 0, 0). */
#include <string.h>

#include "RInternal.h"

static void setGrey(AcmeReal rgb[3], double v)
{
    rgb[0] = rgb[1] = rgb[2] = (AcmeReal)v;
}

void RLightSetDefaults(RRender *rc)
{
    rc->m_bUseAmbientLight = 1;
    for (int i = 0; i < 3; i++)
        rc->m_rgbAmbientLightColor[i] = (AcmeReal)0.2;
    rc->m_rgbAmbientLightColor[3] = 1;

    RDirectLight *d = &rc->m_DirectLight1;
    d->m_Direction[0] = (AcmeReal)0.86, d->m_Direction[1] = (AcmeReal)0.26, d->m_Direction[2] = (AcmeReal)0.43;
    d->m_bUseLight = 1;
    setGrey(d->m_rgbAmbient, 0.7), setGrey(d->m_rgbDiffuse, 0.6), setGrey(d->m_rgbSpecular, 0.5);

    rc->m_DirectLight2 = rc->m_DirectLight1;
    rc->m_DirectLight2.m_Direction[0] = (AcmeReal)-0.86;
    rc->m_DirectLight2.m_bUseLight = 0;

    memset(&rc->m_PointLight, 0, sizeof rc->m_PointLight);
    rc->m_PointLight.m_AttenuationConstant = 1;
}

void MEAPI RLightSwitchOn(RRender *rc, RRenderLight light)
{
    if (!rc)
        return;
    switch (light) {
    case kRAmbient: rc->m_bUseAmbientLight = 1; break;
    case kRDirect1: rc->m_DirectLight1.m_bUseLight = 1; rc->m_bForceDirectLight1Update = 1; break;
    case kRDirect2: rc->m_DirectLight2.m_bUseLight = 1; rc->m_bForceDirectLight2Update = 1; break;
    case kRPoint: rc->m_PointLight.m_bUseLight = 1; rc->m_bForcePointLightUpdate = 1; break;
    default: R_REPORT(ME_ERR_ARGUMENT_RANGE, "RLightSwitchOn", "no light %d", (int)light);
    }
}

void MEAPI RLightSwitchOff(RRender *rc, RRenderLight light)
{
    if (!rc)
        return;
    switch (light) {
    case kRAmbient: rc->m_bUseAmbientLight = 0; break;
    case kRDirect1: rc->m_DirectLight1.m_bUseLight = 0; rc->m_bForceDirectLight1Update = 1; break;
    case kRDirect2: rc->m_DirectLight2.m_bUseLight = 0; rc->m_bForceDirectLight2Update = 1; break;
    case kRPoint: rc->m_PointLight.m_bUseLight = 0; rc->m_bForcePointLightUpdate = 1; break;
    default: R_REPORT(ME_ERR_ARGUMENT_RANGE, "RLightSwitchOff", "no light %d", (int)light);
    }
}
