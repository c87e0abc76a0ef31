/* RHelp.c -- the application's help text (RRenderCreateUserHelp), shown and hidden with F1 or
 * RRenderToggleUserHelp (the simulation pauses while it is shown, as in Karma), and RParseText,
 * which replaces $UP, $ACTION2, $MOUSE, $APPNAME... with the keys of this viewer's key map. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "RInternal.h"

/** Where help starts in Karma's virtual 640 × 448 screen, and its line spacing. */
#define R_HELP_X 20.0f
#define R_HELP_Y 40.0f
#define R_HELP_LINE 18.0f
#define R_HELP_MAX_LINES 40
#define R_HELP_LINE_CHARS 256

/* The text a $NAME stands for, or NULL when NAME is not one of Karma's. */
static const char *substitute(RRender *rc, const char *name, size_t length, char *buffer, size_t size)
{
    static const char *const fixed[][2] = {
        {"UP", "Up arrow"},   {"DOWN", "Down arrow"}, {"LEFT", "Left arrow"}, {"RIGHT", "Right arrow"},
        {"UP2", "w"},         {"DOWN2", "s"},         {"LEFT2", "a"},         {"RIGHT2", "d"},
        {"ACTION0", "h"},     {"ACTION1", "m"},       {"MOUSE", "Ctrl or Shift + mouse"},
        {"JOYSTICK", "joystick"}};
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        if (strlen(fixed[i][0]) == length && strncmp(fixed[i][0], name, length) == 0)
            return fixed[i][1];
    if (length == 7 && strncmp(name, "APPNAME", 7) == 0)
        return rc->m_AppName;
    if (length == 7 && strncmp(name, "ACTION", 6) == 0 && name[6] >= '2' && name[6] <= '5') {
        unsigned char key = rc->m_pCallBacks->m_actionKeys[name[6] - '2'];
        if (key == '\r')
            return "Enter";
        if (key == ' ')
            return "Space";
        snprintf(buffer, size, "%c", key);
        return buffer;
    }
    return NULL;
}

void MEAPI RParseText(RRender *rc, const char *text_in, char *text_out, int outbuffersize)
{
    if (!rc || !text_in || !text_out || outbuffersize < 1) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RParseText", "NULL argument or no room for the text");
        return;
    }
    size_t room = (size_t)outbuffersize - 1, n = 0;
    for (const char *c = text_in; *c && n < room;) {
        const char *with = NULL;
        size_t length = 0;
        char buffer[8];
        if (*c == '$') { /* the longest name that is one of Karma's: $UP2 before $UP */
            while ((c[1 + length] >= 'A' && c[1 + length] <= 'Z') || (c[1 + length] >= '0' && c[1 + length] <= '9'))
                length++;
            for (; length > 0 && !(with = substitute(rc, c + 1, length, buffer, sizeof buffer)); length--)
                ;
        }
        if (with) {
            for (const char *w = with; *w && n < room; w++)
                text_out[n++] = *w;
            c += 1 + length;
        } else {
            text_out[n++] = *c++;
        }
    }
    text_out[n] = 0;
}

static void freeHelp(struct RRenderPrivate *p)
{
    for (int i = 0; i < p->helpCount; i++)
        free(p->help[i]);
    free(p->help);
    p->help = NULL;
    p->helpCount = 0;
}

void MEAPI RRenderCreateUserHelp(RRender *rc, char *help[], int arraySize)
{
    if (!rc || (!help && arraySize > 0) || arraySize < 0) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RRenderCreateUserHelp", "NULL render context or help lines, or a negative count");
        return;
    }
    struct RRenderPrivate *p = rc->m_private;
    if (p->helpShown)
        RRenderToggleUserHelp(rc);
    freeHelp(p);
    int n = arraySize < R_HELP_MAX_LINES ? arraySize : R_HELP_MAX_LINES;
    p->help = calloc((size_t)(n > 0 ? n : 1), sizeof *p->help);
    if (!p->help)
        return;
    for (int i = 0; i < n; i++) {
        p->help[i] = malloc(R_HELP_LINE_CHARS);
        if (!p->help[i])
            break;
        RParseText(rc, help[i] ? help[i] : "", p->help[i], R_HELP_LINE_CHARS);
        p->helpCount = i + 1;
    }
}

/* "key - text" for each callback given with text (RRenderSet...CallBackWithText), as 1.2 listed them
 * after the application's lines, into lines[0 …]; returns how many (at most max). */
static int callbackLines(RRender *rc, char lines[][R_HELP_LINE_CHARS], int max)
{
    static const char *const buttonKeys[kRButtons] = {"$UP", "$DOWN", "$LEFT", "$RIGHT", "$UP2", "$DOWN2", "$LEFT2", "$RIGHT2"};
    const RRenderCallBacks *cb = rc->m_pCallBacks;
    const char *key[kRButtons + 2 + NUM_ACTION_CALLBACKS], *text[kRButtons + 2 + NUM_ACTION_CALLBACKS];
    int n = 0;
    for (int i = 0; i < kRButtons; i++)
        key[n] = buttonKeys[i], text[n++] = cb->m_Button[i].m_CallBack ? cb->m_Button[i].m_Text : NULL;
    key[n] = "$MOUSE", text[n++] = cb->m_Mouse.m_CallBack ? cb->m_Mouse.m_Text : NULL;
    key[n] = "$JOYSTICK", text[n++] = cb->m_Joystick.m_CallBack ? cb->m_Joystick.m_Text : NULL;
    static const char *const actionKeys[NUM_ACTION_CALLBACKS] = {"$ACTION0", "$ACTION1", "$ACTION2", "$ACTION3",
                                                                 "$ACTION4", "$ACTION5"};
    for (int i = 0; i < NUM_ACTION_CALLBACKS; i++)
        key[n] = actionKeys[i], text[n++] = cb->m_Action[i].m_CallBack ? cb->m_Action[i].m_Text : NULL;
    int count = 0;
    for (int i = 0; i < n && count < max; i++) {
        if (!text[i])
            continue;
        char raw[R_HELP_LINE_CHARS];
        snprintf(raw, sizeof raw, "%s - %s", key[i], text[i]);
        RParseText(rc, raw, lines[count++], R_HELP_LINE_CHARS);
    }
    return count;
}

void MEAPI RRenderToggleUserHelp(RRender *rc)
{
    if (!rc)
        return;
    struct RRenderPrivate *p = rc->m_private;
    static const float white[4] = {1, 1, 1, 1}, panel[4] = {0, 0, 0, 0.55f};
    if (p->helpShown) {
        for (int i = 0; i < p->helpTextCount; i++)
            RGraphicDelete(rc, p->helpText[i], 1);
        RGraphicDelete(rc, p->helpPanel, 1);
        free(p->helpText);
        p->helpText = NULL, p->helpPanel = NULL, p->helpTextCount = 0;
        p->helpShown = 0;
        RRenderSetPause(rc, p->pausedBeforeHelp);
        return;
    }
    p->pausedBeforeHelp = rc->m_bPause;
    RRenderSetPause(rc, 1);
    p->helpShown = 1;
    char extra[R_HELP_MAX_LINES][R_HELP_LINE_CHARS];
    int extraCount = callbackLines(rc, extra, R_HELP_MAX_LINES - p->helpCount);
    int total = p->helpCount + extraCount;
    p->helpText = calloc((size_t)(total > 0 ? total : 1), sizeof *p->helpText);
    if (!p->helpText)
        return;
    p->helpPanel = RGraphic2DRectangleCreate(rc, R_HELP_X - 10, R_HELP_Y - 6, 600, R_HELP_LINE * (float)total + 12, panel);
    for (int i = 0; i < total; i++)
        p->helpText[p->helpTextCount++] = RGraphicTextCreate(rc, i < p->helpCount ? p->help[i] : extra[i - p->helpCount],
                                                             R_HELP_X, R_HELP_Y + R_HELP_LINE * (float)i, white);
}

void RHelpContextGone(RRender *rc)
{
    struct RRenderPrivate *p = rc->m_private;
    free(p->helpText);
    p->helpText = NULL, p->helpTextCount = 0; /* the graphics go with the 2D list */
    freeHelp(p);
}
