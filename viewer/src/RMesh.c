/* RMesh.c -- vertex buffers shared between graphics of identical vertices (the 1,000 boxes of one
 * size in a pile hold one buffer and are drawn by one instanced call, RGL.c). Graphics whose
 * vertices change while drawn (lines) keep a buffer of their own, updated in place. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <epoxy/gl.h>

#include "RInternal.h"

/** Floats a vertex: position, normal, texture coordinates. */
#define R_VERTEX_FLOATS 8

/* FNV-1a over the vertex bytes: equal vertices give equal keys; the bytes are compared on a match. */
static unsigned long long hashBytes(const float *data, size_t bytes)
{
    const unsigned char *b = (const unsigned char *)data;
    unsigned long long h = 1469598103934665603ull;
    for (size_t i = 0; i < bytes; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

/* Positions, normals and texture coordinates as floats (8 a vertex), and the radius of the sphere about the origin holding them. */
static float *vertexData(const RGraphic *rg, int n, float *radius)
{
    float *data = malloc(sizeof(float) * R_VERTEX_FLOATS * (size_t)(n > 0 ? n : 1));
    double r2 = 0;
    if (!data)
        return NULL;
    for (int i = 0; i < n; i++) {
        const RObjectVertex *v = &rg->m_pVertices[i];
        float *d = data + R_VERTEX_FLOATS * i;
        d[0] = (float)v->m_X, d[1] = (float)v->m_Y, d[2] = (float)v->m_Z;
        d[3] = (float)v->m_NX, d[4] = (float)v->m_NY, d[5] = (float)v->m_NZ;
        d[6] = (float)v->m_U, d[7] = (float)v->m_V;
        double s = (double)d[0] * d[0] + (double)d[1] * d[1] + (double)d[2] * d[2];
        r2 = s > r2 ? s : r2;
    }
    *radius = (float)sqrt(r2);
    return data;
}

/* The vertices a graphic draws: its count, within what it has room for. */
static int drawnCount(const RGraphic *rg)
{
    int n = rg->m_pObject->m_nNumVertices;
    if (n > rg->m_nMaxNumVertices)
        n = rg->m_nMaxNumVertices;
    return n > 0 ? n : 0;
}

static RMesh *meshNew(RMeshCache *cache, float *data, int n, unsigned long long hash, int shared)
{
    RMesh *m = calloc(1, sizeof *m);
    if (!m)
        return NULL;
    m->hash = hash, m->count = n, m->shared = shared, m->refs = 1, m->data = data;
    glGenVertexArrays(1, &m->vao);
    glGenBuffers(1, &m->vbo);
    glBindVertexArray(m->vao);
    glBindBuffer(GL_ARRAY_BUFFER, m->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * R_VERTEX_FLOATS * (size_t)n), data, GL_STATIC_DRAW);
    const GLsizei stride = R_VERTEX_FLOATS * sizeof(float);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, NULL);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (const void *)(3 * sizeof(float)));
    glVertexAttribPointer(10, 2, GL_FLOAT, GL_FALSE, stride, (const void *)(6 * sizeof(float)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(10);
    RGLInstanceAttributes(cache->instances, 0);
    glBindVertexArray(0);
    if (shared) {
        m->next = cache->meshes;
        cache->meshes = m;
    } else { /* the bytes are only kept to find equal meshes */
        free(m->data);
        m->data = NULL;
    }
    return m;
}

RMesh *RMeshAcquire(RMeshCache *cache, const RGraphic *rg, int shared, float *radius)
{
    int n = drawnCount(rg);
    float *data = vertexData(rg, n, radius);
    if (!data)
        return NULL;
    size_t bytes = sizeof(float) * R_VERTEX_FLOATS * (size_t)n;
    unsigned long long hash = hashBytes(data, bytes);
    if (shared)
        for (RMesh *m = cache->meshes; m; m = m->next)
            if (m->hash == hash && m->count == n && memcmp(m->data, data, bytes) == 0) {
                m->refs++;
                free(data);
                return m;
            }
    RMesh *m = meshNew(cache, data, n, hash, shared);
    if (!m)
        free(data);
    return m;
}

int RMeshUpdate(RMesh *m, const RGraphic *rg, float *radius)
{
    if (m->shared || m->refs != 1)
        return 0;
    int n = drawnCount(rg);
    float *data = vertexData(rg, n, radius);
    if (!data)
        return 0;
    glBindBuffer(GL_ARRAY_BUFFER, m->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * R_VERTEX_FLOATS * (size_t)n), data, GL_DYNAMIC_DRAW);
    m->count = n;
    free(data);
    return 1;
}

void RMeshRelease(RMeshCache *cache, RMesh *m)
{
    if (!m || --m->refs > 0)
        return;
    for (RMesh **link = &cache->meshes; *link; link = &(*link)->next)
        if (*link == m) {
            *link = m->next;
            break;
        }
    glDeleteVertexArrays(1, &m->vao);
    glDeleteBuffers(1, &m->vbo);
    free(m->data);
    free(m);
}
