/* misc.c -- MeHSVtoRGB (see MeMisc.h). */
#include <math.h>

#include <karma/MeMisc.h>

void MEAPI MeHSVtoRGB(float h, float s, float v, float rgb[3])
{
    /* Hue picks one of six sectors of the colour wheel; within it one component rises or falls
     * linearly while the other two sit at the top (v) and the bottom (v (1 - s)). */
    float hue = fmodf(h, 360.0f);
    float sector, f, p, q, t;
    int i;
    if (hue < 0.0f)
        hue += 360.0f;
    sector = hue / 60.0f;
    i = (int)sector;
    f = sector - (float)i;
    p = v * (1.0f - s);
    q = v * (1.0f - s * f);
    t = v * (1.0f - s * (1.0f - f));
    switch (i % 6) {
    case 0: rgb[0] = v; rgb[1] = t; rgb[2] = p; break;
    case 1: rgb[0] = q; rgb[1] = v; rgb[2] = p; break;
    case 2: rgb[0] = p; rgb[1] = v; rgb[2] = t; break;
    case 3: rgb[0] = p; rgb[1] = q; rgb[2] = v; break;
    case 4: rgb[0] = t; rgb[1] = p; rgb[2] = v; break;
    default: rgb[0] = v; rgb[1] = p; rgb[2] = q; break;
    }
}
