#pragma once
// The map stream's layout, as far as the serialization tests cut and corrupt it
// (doc/map-plugin.md, "Serialization"): one place to edit when a version appends a field.
namespace whiskermap::maps::test
{
/** The version CHierarchicalObjectMap writes. */
constexpr int STREAM_VERSION = 17;
/** Version 14's tail: manhattan_walls (a bool), wall_axis, wall_extension and
 *  wall_extension_min_length (doubles). */
constexpr long MANHATTAN_BYTES = 1 + 8 + 8 + 8;
/** Version 15's tail: record_swept (a bool). */
constexpr long RECORD_SWEPT_BYTES = 1;
/** Version 16's tail: leg_merge_gap (a double). */
constexpr long LEG_MERGE_GAP_BYTES = 8;
/** Version 17's tail: disjoint_tables (a bool). */
constexpr long DISJOINT_BYTES = 1;
/** What the versions after 16 write after version 16's tail, before MRPT's end flag. */
constexpr long AFTER_LEG_MERGE_GAP = DISJOINT_BYTES;
/** What the versions after 14 write after version 14's tail, before MRPT's end flag. */
constexpr long AFTER_MANHATTAN = RECORD_SWEPT_BYTES + LEG_MERGE_GAP_BYTES + AFTER_LEG_MERGE_GAP;
/** What the versions after 13 write after version 13's chain spreads, before MRPT's end flag. */
constexpr long AFTER_CHAIN_SPREADS = MANHATTAN_BYTES + AFTER_MANHATTAN;
}  // namespace whiskermap::maps::test
