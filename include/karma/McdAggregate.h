/* McdAggregate.h -- Karma 1.2's aggregate: a compound geometry of elements, each a geometry (shared,
 * of any type, aggregates included) at a transform relative to the aggregate.
 *
 * An element holds a reference on its geometry: McdGeometryDestroy refuses it (ME_ERR_MCD_IN_USE)
 * until the element is removed or the aggregate destroyed. A model of an aggregate has one geometry
 * instance per element slot (McdGeometryInstance.h, from McdInit's instanceCount pool); contacts name
 * the element's instance in element1 / element2. Changes to an aggregate reach its models at their
 * next update, as a geometry's dimensions do.
 *
 * Mass properties (McdGeometryGetMassProperties) combine the elements' for unit density (overlaps
 * counted twice, as Karma); the centre-of-mass frame has the aggregate's axes. A segment hits the
 * first element it meets (one hit per model, as Karma). */
#ifndef MCD_AGGREGATE_H
#define MCD_AGGREGATE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** An empty aggregate of at most maxChildren (1 ... 65536) elements; NULL (reported) when out of
 *  range or the framework's geometry pool is full. */
ME_API McdAggregateID McdAggregateCreate(McdFramework *frame, int maxChildren);
/** Add `element` at relTM (copied; a rigid transform, in range) in the first empty slot; returns the
 *  slot, or -1 (reported): aggregate full (ME_ERR_MCD_AGGREGATE_FULL), bad transform
 *  (ME_ERR_MCD_AGGREGATE_TRANSFORM), element containing the aggregate or nesting deeper than 16
 *  (ME_ERR_MCD_AGGREGATE_CYCLE), foreign or invalid element. */
ME_API int McdAggregateAddElement(McdAggregateID aggregate, McdGeometryID element, MeMatrix4 relTM);
/** Empty slot `index`, releasing its geometry; an index out of range or an empty slot is refused
 *  (ME_ERR_MCD_AGGREGATE_INDEX). */
ME_API void McdAggregateRemoveElement(McdAggregateID aggregate, int index);
/** Elements held; 0 for an invalid ID (reported). */
ME_API int McdAggregateGetElementCount(McdAggregateID aggregate);
/** Slots (maxChildren at creation); 0 for an invalid ID (reported). */
ME_API int McdAggregateGetElementCountMax(McdAggregateID aggregate);
/** The geometry in slot i, NULL for an empty slot; out of range: NULL, reported (ME_ERR_MCD_AGGREGATE_INDEX). */
ME_API McdGeometryID McdAggregateGetElementGeometry(McdAggregateID aggregate, int i);
/** The stored relative transform of slot i (writable, as Karma's: keep it rigid; models see a change at
 *  their next update); NULL for an empty slot or out of range (reported). */
ME_API MeMatrix4Ptr McdAggregateGetElementTransformPtr(McdAggregateID aggregate, int i);
/** Destroy an aggregate (McdGeometryDestroy: refused while used); another type refused. */
ME_API void McdAggregateDestroy(McdAggregateID aggregate);
/** The aggregate type's number (kMcdGeometryTypeAggregate, 8, as Karma's). */
ME_API MeI16 McdAggregateGetTypeId(void);
/** The type's name, "Aggregate". */
ME_API const char *McdAggregateGetTypeName(void);
/** Nothing to do: the type exists from McdInit on (kept for Karma code). */
ME_API void McdAggregateRegisterType(McdFramework *frame);
/** Register the aggregate's pair test against every geometry type the framework knows (primitives,
 *  convex meshes, plane, terrain, aggregates, user types registered so far); METRUE. */
ME_API MeBool McdAggregateGenericRegisterInteractions(McdFrameworkID frame);
/** Nothing to do: aggregates answer segment queries from McdInit on (kept for Karma code). */
ME_API void McdAggregateLineSegmentRegisterInteraction(McdFrameworkID frame);
/** McdAggregateGenericRegisterInteractions and the segment test (Karma's one call). */
ME_API void McdAggregateRegisterInteractions(McdFrameworkID frame);
/** Unit-density mass properties of the aggregate (McdGeometryGetMassProperties); 0 on success,
 *  non-zero (reported, ME_ERR_MCD_AGGREGATE_MASS) when an element has no finite volume. */
ME_API MeI16 McdAggregateGetMassProperties(McdAggregateID aggregate, MeMatrix4 relTM, MeMatrix3 inertia,
                                           MeReal *volume);
/** Draw the elements at tm through MeDebugDraw (McdGeometryDebugDraw). */
ME_API void McdAggregateDebugDraw(McdAggregateID aggregate, MeMatrix4 tm, const MeReal colour[3]);

ME_EXTERN_C_END

#endif /* MCD_AGGREGATE_H */
