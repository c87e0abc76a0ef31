/* MeMisc.h -- small utilities of Karma's demos: colour conversion and circular-list macros. */
#ifndef ME_MISC_H
#define ME_MISC_H

#include "MeAssert.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** rgb = the colour of hue h (degrees, any value: taken modulo 360), saturation s and value v (both
 *  0..1); each component in 0..1. */
ME_API void MEAPI MeHSVtoRGB(float h, float s, float v, float rgb[3]);

/* Circular doubly linked lists with a sentinel node. A node type has `next`, `prev` and `current`
 * (the item it holds); the sentinel is a node whose `current` is 0. */

/** Make the list empty. */
#define LIST_INIT_SENTINEL(sentinel)                                                                 \
    MEASSERT((sentinel));                                                                            \
    (sentinel)->next = (sentinel)->prev = (sentinel);                                                \
    (sentinel)->current = 0;
/** Insert node at the front. */
#define LIST_INSERT(node, sentinel)                                                                  \
    MEASSERT((node));                                                                                \
    MEASSERT((sentinel));                                                                            \
    (node)->next = (sentinel)->next;                                                                 \
    (sentinel)->next->prev = (node);                                                                 \
    (sentinel)->next = (node);                                                                       \
    (node)->prev = (sentinel);
/** Unlink the node holding item, searching from the back; node is left pointing at it. */
#define LIST_REMOVE(node, sentinel, item)                                                            \
    MEASSERT((sentinel));                                                                            \
    MEASSERT((item));                                                                                \
    (node) = (sentinel)->prev;                                                                       \
    while ((node) != (sentinel) && ((node)->current != (item)))                                      \
        (node) = (node)->prev;                                                                       \
    (node)->prev->next = (node)->next;                                                               \
    (node)->next->prev = (node)->prev;
/** Unlink the last node; node is left pointing at it. */
#define LIST_REMOVE_THIS(node, sentinel)                                                             \
    MEASSERT((sentinel));                                                                            \
    (node) = (sentinel)->prev;                                                                       \
    (node)->prev->next = (node)->next;                                                               \
    (node)->next->prev = (node)->prev;
/** Nonzero when the list holds no node. */
#define LIST_IS_EMPTY(sentinel) ((sentinel)->next == (sentinel) && (sentinel)->prev == (sentinel))

ME_EXTERN_C_END

#endif /* ME_MISC_H */
