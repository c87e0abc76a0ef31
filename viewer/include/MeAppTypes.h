/* MeAppTypes.h -- the structures of MeApp, Karma's demo support (mouse picking and dragging, contact
 * drawing), under Karma 1.2's names and fields. One MeApp serves one world (or universe), one space
 * and one render context. */
#ifndef ME_APP_TYPES_H
#define ME_APP_TYPES_H

#include <karma/MdtTypes.h>
#include <karma/McdTypes.h>
#include <karma/MstTypes.h>

#include "MeViewerTypes.h"

typedef struct MeApp MeApp;
typedef struct MeAppContactDrawInfo MeAppContactDrawInfo;
typedef struct MeAppMousePickInfo MeAppMousePickInfo;

/** The mouse spring: which body is dragged, by which point, towards where. */
struct MeAppMousePickInfo {
    RGraphic *line;                /**< the rubber band, from the grabbed point to desiredPosition */
    MdtBodyID dragBody;            /**< the body being dragged, NULL when none */
    MeVector3 grabPosition;        /**< the grabbed point in the body's frame */
    MeVector3 desiredPosition;     /**< where the grabbed point is pulled to (world) */
    MeReal range;                  /**< distance from the camera to the grabbed point when picked */
    MeReal mouseSpringStiffness;   /**< per unit of the body's mass (1/s²); 25 by default */
    MeReal mouseSpringDamping;     /**< per unit of the body's mass (1/s); 2.8 by default */
};

/** Demo support for one world and space (and the universe holding them, if made from one) and one
 *  render context. */
struct MeApp {
    MdtWorldID world;
    McdSpaceID space;               /**< NULL: nothing can be picked */
    MstUniverseID universe;         /**< NULL unless made by MeAppCreateFromUniverse */
    RRender *rc;
    MeAppContactDrawInfo *contactDrawInfo; /**< NULL until MeAppDrawContactsInit */
    MeBool drawContacts;
    MeAppMousePickInfo mouseInfo;
};

/** Contact drawing: a pool of lines, one per contact drawn. */
struct MeAppContactDrawInfo {
    RGraphic **contactG;   /**< maxContacts lines (owned by the render context) */
    float color[4];
    int maxContacts;
    int contactsDrawn;     /**< contacts drawn by the last MeAppDrawContacts */
    MeReal length;         /**< length of a contact's line along its normal (1 by default) */
};

#endif /* ME_APP_TYPES_H */
