/* RMenu.c -- Karma's on-screen menus: a title and entries drawn as 2D text over a dark panel;
 * while one is shown the arrows work it (Up/Down choose an entry; Right and Left flip a toggle,
 * raise and lower a value by its step within its bounds, open a submenu); the menu key (m, action
 * 1) shows and hides the default menu, F12 the viewer's own (pause, single step, wireframe,
 * shadows, frame rate, performance bar, help, exit). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "RInternal.h"

/** Layout in Karma's virtual 640 × 448 screen: the title's top left, the line spacing, where values sit. */
#define R_MENU_X 200.0f
#define R_MENU_Y 30.0f
#define R_MENU_LINE 25.0f
#define R_MENU_VALUE_X 300.0f
#define R_MENU_NAME 64

typedef enum { kREntryToggle, kREntryValue, kREntrySubmenu, kREntryViewer } REntryKind;

typedef struct RMenuEntry {
    REntryKind kind;
    char name[R_MENU_NAME];
    RMenuToggleCallback toggle;
    RMenuValueCallback value;
    RMenu *submenu;
    RViewerEntryFn viewer;   /* kREntryViewer: reads (set < 0) or sets the viewer's state */
    MeBool on;
    MeReal v, lo, hi, step;
    RGraphic *nameText, *valueText;
} RMenuEntry;

struct RMenu {
    RRender *rc;             /* NULL once the context is gone */
    RMenu *next;             /* in the context's list of menus */
    char name[R_MENU_NAME];
    RMenuEntry *entries;
    int count, capacity, current;
    RGraphic *title, *panel;
};

static const float textColor[4] = {1, 0.25f, 0.2f, 1}, highlightColor[4] = {1, 1, 0, 1},
                   titleColor[4] = {1, 1, 1, 1}, panelColor[4] = {0, 0, 0, 0.55f};

RMenu *MEAPI RMenuCreate(RRender *rc, const char *name)
{
    if (!rc || !name) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RMenuCreate", "NULL %s", rc ? "name" : "render context");
        return NULL;
    }
    RMenu *rm = calloc(1, sizeof *rm);
    if (!rm)
        return NULL;
    rm->rc = rc;
    snprintf(rm->name, sizeof rm->name, "%s", name);
    rm->next = rc->m_private->menus;
    rc->m_private->menus = rm;
    return rm;
}

static RMenuEntry *addEntry(RMenu *rm, REntryKind kind, const char *name, const char *fn)
{
    if (!rm || !name) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, fn, "NULL %s", rm ? "name" : "menu");
        return NULL;
    }
    if (rm->count == rm->capacity) {
        int capacity = rm->capacity ? 2 * rm->capacity : 8;
        RMenuEntry *e = realloc(rm->entries, sizeof *e * (size_t)capacity);
        if (!e)
            return NULL;
        rm->entries = e, rm->capacity = capacity;
    }
    RMenuEntry *e = &rm->entries[rm->count++];
    memset(e, 0, sizeof *e);
    e->kind = kind;
    snprintf(e->name, sizeof e->name, "%s", name);
    return e;
}

void MEAPI RMenuAddToggleEntry(RMenu *rm, const char *name, RMenuToggleCallback func, MeBool defaultValue)
{
    RMenuEntry *e = addEntry(rm, kREntryToggle, name, "RMenuAddToggleEntry");
    if (e)
        e->toggle = func, e->on = defaultValue ? METRUE : MEFALSE;
}

/* Size: Karma 1.2's signature. */
void MEAPI RMenuAddValueEntry(RMenu *rm, const char *name, RMenuValueCallback func, MeReal hi, MeReal lo,
                              MeReal increment, MeReal defaultValue)
{
    if (!(lo <= hi) || !(increment > 0)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RMenuAddValueEntry", "'%s' needs lo <= hi and increment > 0 (lo %g, hi %g, increment %g)",
                 name ? name : "(null)", (double)lo, (double)hi, (double)increment);
        return;
    }
    RMenuEntry *e = addEntry(rm, kREntryValue, name, "RMenuAddValueEntry");
    if (!e)
        return;
    e->value = func, e->lo = lo, e->hi = hi, e->step = increment;
    e->v = defaultValue > hi ? hi : defaultValue < lo ? lo : defaultValue; /* as 1.2: kept within bounds */
}

void MEAPI RMenuAddSubmenuEntry(RMenu *rm, const char *name, RMenu *submenu)
{
    RMenuEntry *e = addEntry(rm, kREntrySubmenu, name, "RMenuAddSubmenuEntry");
    if (e)
        e->submenu = submenu;
}

void RMenuAddViewerEntry(RMenu *rm, const char *name, RViewerEntryFn fn)
{
    RMenuEntry *e = addEntry(rm, kREntryViewer, name, "RMenuAddViewerEntry");
    if (e)
        e->viewer = fn;
}

/* What an entry shows after its name. */
static void valueText(const RMenu *rm, const RMenuEntry *e, char *out, size_t size)
{
    switch (e->kind) {
    case kREntryToggle: snprintf(out, size, "%s", e->on ? "YES" : "NO"); break;
    case kREntryValue: snprintf(out, size, "% .2f", (double)e->v); break;
    case kREntryViewer: {
        int state = e->viewer(rm->rc, -1);
        snprintf(out, size, "%s", state < 0 ? "" : state ? "YES" : "NO");
        break;
    }
    default: out[0] = 0; break;
    }
}

static void showEntry(RMenu *rm, int i)
{
    RMenuEntry *e = &rm->entries[i];
    RRender *rc = rm->rc;
    float y = R_MENU_Y + R_MENU_LINE * (float)(i + 1);
    const float *color = i == rm->current ? highlightColor : textColor;
    char text[32];
    valueText(rm, e, text, sizeof text);
    if (!e->nameText)
        e->nameText = RGraphicTextCreate(rc, e->name, R_MENU_X, y, color);
    RGraphicSetColor(e->nameText, color);
    if (e->valueText)
        RGraphicDelete(rc, e->valueText, 1);
    e->valueText = text[0] ? RGraphicTextCreate(rc, text, R_MENU_X + R_MENU_VALUE_X, y, color) : NULL;
}

static void hide(RMenu *rm)
{
    RRender *rc = rm->rc;
    for (int i = 0; i < rm->count; i++) {
        RGraphicDelete(rc, rm->entries[i].nameText, 1);
        RGraphicDelete(rc, rm->entries[i].valueText, 1);
        rm->entries[i].nameText = rm->entries[i].valueText = NULL;
    }
    RGraphicDelete(rc, rm->title, 1);
    RGraphicDelete(rc, rm->panel, 1);
    rm->title = rm->panel = NULL;
    if (rc && rc->m_private->menuShown == rm)
        rc->m_private->menuShown = NULL;
}

void MEAPI RMenuDisplay(RMenu *rm)
{
    if (!rm || !rm->rc)
        return;
    RRender *rc = rm->rc;
    if (rc->m_private->menuShown)
        hide(rc->m_private->menuShown);
    rc->m_private->menuShown = rm;
    rm->panel = RGraphic2DRectangleCreate(rc, R_MENU_X - 10, R_MENU_Y - 5, R_MENU_VALUE_X + 120,
                                          R_MENU_LINE * (float)(rm->count + 1) + 5, panelColor);
    rm->title = RGraphicTextCreate(rc, rm->name, R_MENU_X, R_MENU_Y, titleColor);
    if (rm->current >= rm->count)
        rm->current = 0;
    for (int i = 0; i < rm->count; i++)
        showEntry(rm, i);
}

void MEAPI RRenderSetDefaultMenu(RRender *rc, RMenu *menu)
{
    if (rc)
        rc->m_private->menuDefault = menu;
}

void MEAPI RMenuDestroy(RMenu *rm)
{
    if (!rm)
        return;
    if (rm->rc) {
        struct RRenderPrivate *p = rm->rc->m_private;
        if (p->menuShown == rm)
            hide(rm);
        if (p->menuDefault == rm)
            p->menuDefault = NULL;
        for (RMenu **link = &p->menus; *link; link = &(*link)->next)
            if (*link == rm) {
                *link = rm->next;
                break;
            }
        for (RMenu *other = p->menus; other; other = other->next) /* no submenu entry left pointing here */
            for (int i = 0; i < other->count; i++)
                if (other->entries[i].submenu == rm)
                    other->entries[i].submenu = NULL;
    }
    free(rm->entries);
    free(rm);
}

void RMenuContextGone(RRender *rc)
{
    struct RRenderPrivate *p = rc->m_private;
    if (p->menuShown)
        hide(p->menuShown);
    RMenuDestroy(p->menuViewer);
    p->menuViewer = NULL;
    for (RMenu *m = p->menus; m; m = m->next)
        m->rc = NULL; /* the application's menus stay its to destroy */
    p->menus = NULL;
}

/* Right (up = 1) or Left (up = 0) on the current entry. */
static void execute(RMenu *rm, int up)
{
    RMenuEntry *e = &rm->entries[rm->current];
    switch (e->kind) {
    case kREntryToggle:
        e->on = !e->on;
        if (e->toggle)
            e->toggle(e->on);
        break;
    case kREntryValue:
        e->v = up ? (e->v + e->step > e->hi ? e->hi : e->v + e->step) : (e->v - e->step < e->lo ? e->lo : e->v - e->step);
        if (e->value)
            e->value(e->v);
        break;
    case kREntrySubmenu:
        if (e->submenu)
            RMenuDisplay(e->submenu);
        return;
    case kREntryViewer:
        e->viewer(rm->rc, up);
        if (rm->rc->m_private->menuShown != rm) /* the entry closed the menu (exit, help) */
            return;
        break;
    }
    showEntry(rm, rm->current);
}

int RMenuKey(RRender *rc, int key)
{
    RMenu *rm = rc->m_private->menuShown;
    if (!rm || rm->count == 0)
        return 0;
    int before = rm->current;
    switch (key) {
    case RKEY_UP: rm->current = (rm->current + rm->count - 1) % rm->count; break;
    case RKEY_DOWN: rm->current = (rm->current + 1) % rm->count; break;
    case RKEY_RIGHT: execute(rm, 1); return 1;
    case RKEY_LEFT: execute(rm, 0); return 1;
    default: return 0;
    }
    showEntry(rm, before);
    showEntry(rm, rm->current);
    return 1;
}

void RMenuToggle(RRender *rc, RMenu *rm)
{
    struct RRenderPrivate *p = rc->m_private;
    if (p->menuShown) {
        RMenu *was = p->menuShown;
        hide(was);
        if (was == rm)
            return;
    }
    if (rm)
        RMenuDisplay(rm);
}
