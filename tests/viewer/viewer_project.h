/* viewer_project.h -- where a world point lands on a render context's picture, computed from the
 * camera's matrices as the viewer documents them: clip = (p, 1)·m_CamMatrix·m_ProjMatrix. Shared by
 * the viewer's tests, which compare it with the geometry and with the pictures. */
#ifndef KARMA_VIEWER_PROJECT_H
#define KARMA_VIEWER_PROJECT_H

#include <MeViewer.h>

/** Normalised device coordinates of p in ndc[0..2]; returns the clip w (> 0 in front of the camera). */
static inline double viewerProject(RRender *rc, const double p[3], double ndc[3])
{
    double e[4], c[4], h[4] = {p[0], p[1], p[2], 1};
    for (int j = 0; j < 4; j++) {
        e[j] = 0;
        for (int i = 0; i < 4; i++)
            e[j] += h[i] * rc->m_CamMatrix[i][j];
    }
    for (int j = 0; j < 4; j++) {
        c[j] = 0;
        for (int i = 0; i < 4; i++)
            c[j] += e[i] * rc->m_ProjMatrix[i][j];
    }
    for (int k = 0; k < 3; k++)
        ndc[k] = c[k] / c[3];
    return c[3];
}

#endif /* KARMA_VIEWER_PROJECT_H */
