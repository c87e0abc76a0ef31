/* MdtContactParams.h -- the physical parameters of a contact: friction, restitution, softness,
 * adhesion, slip and slide.
 *
 * Parameters are a plain struct, copied by value into each contact (the bridge copies them from its
 * material table), so that an application may change them per contact. Defaults (Karma's): a
 * frictionless contact (MdtContactTypeFrictionZero); friction model Box with an infinite force
 * bound (no sliding once friction is switched on) and coefficient 0; restitution 0 above an approach
 * speed of 0.001; softness 0; no adhesion, slip or slide.
 *
 * Friction models. Box: the friction force along a direction is bounded by a constant
 * (SetPrimaryFriction, N), whatever the load. NormalForce: bounded by coefficient × normal force
 * (Coulomb). Karma bounded it by the previous step's normal force; we solve the bound with the
 * current normal force (the solver starts from the previous one), which gives the same answer in
 * steady sliding and the right one on impact (docs/decisions.md).
 *
 * Setting softness, adhesion, slip, slide or a restitution above 0 also sets the matching option bit,
 * as Karma did; the bits can be read and changed through `options`. */
#ifndef MDT_CONTACT_PARAMS_H
#define MDT_CONTACT_PARAMS_H

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** Which friction directions a contact has. */
typedef enum MdtContactType {
    MdtContactTypeFrictionZero = 0, /**< normal only: 1 row */
    MdtContactTypeFriction1D = 1,   /**< normal + primary direction: 2 rows */
    MdtContactTypeFriction2D = 2    /**< normal + two directions: 3 rows */
} MdtContactType;

/** How a friction direction's force bound is found. */
typedef enum MdtFrictionModel {
    MdtFrictionModelBox = 0,        /**< constant bound (N) */
    MdtFrictionModelNormalForce = 1 /**< coefficient × normal force */
} MdtFrictionModel;

/* Option bits (params.options). */
#define MdtBclContactOptionUseDirection 0x1     /**< primary direction given by MdtContactSetDirection */
#define MdtBclContactOptionBounce 0x2           /**< restitution */
#define MdtBclContactOptionSoft 0x4             /**< softness */
#define MdtBclContactOptionAdhesive 0x8         /**< may pull, up to max_adhesive_force */
#define MdtBclContactOptionSlip1 0x10           /**< first-order slip along the primary direction */
#define MdtBclContactOptionSlip2 0x20
#define MdtBclContactOptionSlide1 0x40          /**< surface velocity (conveyor) along the primary */
#define MdtBclContactOptionSlide2 0x80
#define MdtBclContactOptionUseWorldVelocity 0x100 /**< the world at this contact moves (body 1 NULL) */

/** A contact's parameters. The struct is Karma 1.2's `struct MdtBclContactParams`, with its fields in
 *  1.2's order; MdtContactParams and MdtBclContactParams name the same type. */
struct MdtBclContactParams {
    MdtContactType type;
    MdtFrictionModel model1, model2;   /**< primary, secondary direction */
    MeU32 options;                     /**< MdtBclContactOption... bits */
    MeReal restitution;                /**< 0 ... 1 */
    MeReal velThreshold;               /**< restitution only above this approach speed, m/s */
    MeReal softness;                   /**< added to the normal row's ε (velocity per impulse, 1/kg) */
    MeReal max_adhesive_force;         /**< N */
    MeReal friction1;                  /**< Box model bound along the primary direction, N (MEINFINITY: no sliding) */
    MeReal frictioncoeff1;             /**< NormalForce model coefficient along the primary direction */
    MeReal slip1;                      /**< tangential compliance: slip speed per friction force, s/kg (m/s per N) */
    MeReal friction2, frictioncoeff2, slip2; /**< the same along the secondary direction */
    MeReal slide1, slide2;             /**< surface velocity along the directions, m/s: the contact drives the
                                            velocity of body 0 relative to body 1 at the contact along the
                                            direction to it (a body on the world moves at +slide) */
};
typedef struct MdtBclContactParams MdtContactParams;
typedef struct MdtBclContactParams MdtBclContactParams; /**< Karma 1.2's name for the type */

/** Parameters are addressed through a plain pointer (inside a contact or a material table). */
typedef MdtContactParams *MdtContactParamsID;

/** Back to the defaults: frictionless (MdtContactTypeFrictionZero), no restitution, softness 0. */
ME_API void MdtContactParamsReset(MdtContactParamsID p);

/** The parameters' values (see the setters below for their meaning and units). */
ME_API MdtContactType MdtContactParamsGetType(MdtContactParamsID p);
/** Friction model of the primary direction; NULL p refused (ME_ERR_NULL_ARGUMENT). */
ME_API MdtFrictionModel MdtContactParamsGetPrimaryFrictionModel(MdtContactParamsID p);
/** Friction model of the secondary direction; NULL p refused (ME_ERR_NULL_ARGUMENT). */
ME_API MdtFrictionModel MdtContactParamsGetSecondaryFrictionModel(MdtContactParamsID p);
/** Restitution, 0 ... 1; NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetRestitution(MdtContactParamsID p);
/** Approach speed (m/s) above which restitution applies; NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetRestitutionThreshold(MdtContactParamsID p);
/** Softness added to the normal row's ε (1/kg); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetSoftness(MdtContactParamsID p);
/** Largest pulling force the contact may apply (N); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetMaxAdhesiveForce(MdtContactParamsID p);
/** Box-model force bound along the primary direction (N); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetPrimaryFriction(MdtContactParamsID p);
/** Coulomb coefficient along the primary direction; NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetPrimaryFrictionCoeffecient(MdtContactParamsID p);
/** Slip along the primary direction (s/kg, m/s per N); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetPrimarySlip(MdtContactParamsID p);
/** Surface velocity along the primary direction (m/s); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetPrimarySlide(MdtContactParamsID p);
/** Box-model force bound along the secondary direction (N); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetSecondaryFriction(MdtContactParamsID p);
/** Coulomb coefficient along the secondary direction; NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetSecondaryFrictionCoeffecient(MdtContactParamsID p);
/** Slip along the secondary direction (s/kg); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetSecondarySlip(MdtContactParamsID p);
/** Surface velocity along the secondary direction (m/s); NULL p refused (returns 0). */
ME_API MeReal MdtContactParamsGetSecondarySlide(MdtContactParamsID p);

/** Friction: none, one direction or two (MdtContactTypeFrictionZero/1D/2D), and the friction
 *  model of each direction (box: a force cap; normal force: Coulomb, a coefficient). */
ME_API void MdtContactParamsSetType(MdtContactParamsID p, MdtContactType t);
/** Friction model of the primary direction; a value outside MdtFrictionModel refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void MdtContactParamsSetPrimaryFrictionModel(MdtContactParamsID p, MdtFrictionModel m);
/** Friction model of the secondary direction; a value outside MdtFrictionModel refused. */
ME_API void MdtContactParamsSetSecondaryFrictionModel(MdtContactParamsID p, MdtFrictionModel m);
/** Both directions. */
ME_API void MdtContactParamsSetFrictionModel(MdtContactParamsID p, MdtFrictionModel m);
/** Restitution r in [0, 1] (sets the bounce bit when > 0); NaN refused, outside [0, 1] ME_ERR_ARGUMENT_RANGE. */
ME_API void MdtContactParamsSetRestitution(MdtContactParamsID p, MeReal r);
/** Approach speed (m/s, ≥ 0) below which there is no bounce; NaN, infinite or negative refused. */
ME_API void MdtContactParamsSetRestitutionThreshold(MdtContactParamsID p, MeReal v);
/** Softness s ≥ 0 (1/kg; sets the soft bit when > 0); NaN, infinite or negative refused (ME_ERR_NEGATIVE_VALUE). */
ME_API void MdtContactParamsSetSoftness(MdtContactParamsID p, MeReal s);
/** Largest pulling force f ≥ 0 (N; MEINFINITY allowed; sets the adhesive bit); NaN or negative refused. */
ME_API void MdtContactParamsSetMaxAdhesiveForce(MdtContactParamsID p, MeReal f);
/** Box-model bound along the primary direction (N, ≥ 0, MEINFINITY: no sliding); NaN or negative refused. */
ME_API void MdtContactParamsSetPrimaryFriction(MdtContactParamsID p, MeReal f);
/** Coulomb coefficient along the primary direction (≥ 0, finite); NaN or negative refused. */
ME_API void MdtContactParamsSetPrimaryFrictionCoeffecient(MdtContactParamsID p, MeReal f);
/** Slip along the primary direction (s/kg, ≥ 0, finite; sets the slip bit); NaN or negative refused. */
ME_API void MdtContactParamsSetPrimarySlip(MdtContactParamsID p, MeReal s);
/** Surface velocity along the primary direction (m/s, any sign; sets the slide bit); NaN refused. */
ME_API void MdtContactParamsSetPrimarySlide(MdtContactParamsID p, MeReal s);
/** Box-model bound along the secondary direction (N, ≥ 0, MEINFINITY allowed); NaN or negative refused. */
ME_API void MdtContactParamsSetSecondaryFriction(MdtContactParamsID p, MeReal f);
/** Coulomb coefficient along the secondary direction (≥ 0, finite); NaN or negative refused. */
ME_API void MdtContactParamsSetSecondaryFrictionCoeffecient(MdtContactParamsID p, MeReal f);
/** Slip along the secondary direction (s/kg, ≥ 0, finite; sets the slip bit); NaN or negative refused. */
ME_API void MdtContactParamsSetSecondarySlip(MdtContactParamsID p, MeReal s);
/** Surface velocity along the secondary direction (m/s; sets the slide bit); NaN or infinite refused. */
ME_API void MdtContactParamsSetSecondarySlide(MdtContactParamsID p, MeReal s);
/** Both directions. */
ME_API void MdtContactParamsSetFriction(MdtContactParamsID p, MeReal f);
/** Coulomb coefficient of both directions (≥ 0, finite); NaN, infinite or negative refused. */
ME_API void MdtContactParamsSetFrictionCoeffecient(MdtContactParamsID p, MeReal f);
/** Slip of both directions (s/kg, ≥ 0, finite; sets both slip bits); NaN or negative refused. */
ME_API void MdtContactParamsSetSlip(MdtContactParamsID p, MeReal s);

ME_EXTERN_C_END

#endif /* MDT_CONTACT_PARAMS_H */
