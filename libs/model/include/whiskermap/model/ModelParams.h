#pragma once
#include <whiskermap/core/IniSection.h>
#include <whiskermap/model/ObjectClass.h>
#include <whiskermap/model/Table.h>

#include <optional>
#include <string>
#include <vector>

namespace whiskermap::model
{
/** Every constant of the generative model (paper sections 3-5), SI units (metres, radians).
 *  Defaults and the reasons for them: config/whisker-map.ini [MetricMap_hierarchicalObjectMap_00_model] and doc/model.md. */
struct ModelParams
{
	// Noise of the part-whole relations (eqs. 6-7)
	double sigma_r = 0.01;  ///< position, metres
	double sigma_theta = 0.087;  ///< angle, radians (5 degrees)
	double sigma_w = 0.01;  ///< leg width, metres
	double sigma_tau = 0.1;  ///< texture
	/** Eq. 6's position noise: a leg's centre against its table's corner, metres (optional key,
	 *  default sigma_r). The furniture's own precision: the lasting map never raises it to a
	 *  sweep's reported noise (CHierarchicalObjectMap::modelFor; doc/model.md, "Two noises"). */
	double sigma_corner = 0.01;
	/** A leg's pull towards its table's corner in a closed-form leg fit (PoseFit.h), in units of
	 *  one contact's weight 1 / sigma_r^2: (sigma_r / sigma_corner)^2. */
	double cornerPull() const { return (sigma_r / sigma_corner) * (sigma_r / sigma_corner); }
	/** Readings looser than the legs' placement (the lasting map with a noisy sensor): legs
	 *  are refitted towards their corners when adopted, and the lasting map revises. */
	bool cornersTighterThanReadings() const { return sigma_corner < sigma_r; }
	/** Contact noise along the whisker's shaft (doc/model.md, "Shaft noise"): a contact's
	 *  distance across a face with outward normal u has variance
	 *  sigma_r^2 (u . shaft)^2 + sigma_across^2 instead of the paper's sigma_r^2 (eq. 7). */
	bool shaft_noise = false;
	double sigma_across = 0.002;  ///< position noise across the shaft, metres

	// Priors (eqs. 4, 5, 7, 8, 9): densities, not normalised
	double c_T = 1e-2;  ///< flat table prior (eq. 4)
	double c_L = 1e-3;  ///< leg without a table (eq. 8)
	double c_S = 1e-4;  ///< shapelet without a leg (eq. 9)
	double alpha_L = 7e3;  ///< scale of p(L | T) (eq. 5)
	double alpha_S = 1e7;  ///< scale of p(S | L) (eq. 7)

	double epsilon = 1e-2;  ///< constraint factor base (eqs. 15-17)
	double delta = 0.01;  ///< half-width of a hypothesis cell in (x, y, theta) (eq. 19)

	// The known table (strong prior)
	double table_length = 1.0;  ///< leg-centre spacing along the table's x axis, metres
	double table_width = 0.6;  ///< leg-centre spacing along its y axis, metres
	double leg_width = 0.05;  ///< side of a square leg, metres
	double texture = 0.7;  ///< texture of table legs (the paper arena's)

	/** The object catalogue (optional key `objects`: a file resolved relative to the config;
	 *  doc/formats.md): the classes a table hypothesis can have (Table::cls indexes them).
	 *  Empty: one class, the known table above (table_length, table_width, leg_width, texture). */
	std::vector<ObjectClass> classes;

	int classCount() const { return classes.empty() ? 1 : static_cast<int>(classes.size()); }
	double lengthOf(int k) const { return classes.empty() ? table_length : classes[k].length; }
	double widthOf(int k) const { return classes.empty() ? table_width : classes[k].width; }
	double legWidthOf(int k) const { return classes.empty() ? leg_width : classes[k].leg_width; }
	double textureOf(int k) const { return classes.empty() ? texture : classes[k].texture; }
	double priorOf(int k) const { return classes.empty() ? 1.0 : classes[k].prior; }
	std::string nameOf(int k) const { return classes.empty() ? "table" : classes[k].label; }
	/** A table's own leg-centre spacings: its class's plus its offsets. */
	double lengthOf(const Table& t) const { return lengthOf(t.cls) + t.d_length; }
	double widthOf(const Table& t) const { return widthOf(t.cls) + t.d_width; }
	/** Spread of a class's length and width about its nominal ones (eq. 24); 0 without a catalogue. */
	double sizeSigmaOf(int k) const { return classes.empty() ? 0.0 : classes[k].size_sigma; }
	/** Whether some class lets its objects' leg width or texture differ from its nominal ones
	 *  (a leg_width_sigma or texture_sigma > 0: eq. 26). */
	bool legsVary() const;
	/** Whether some class lets its objects' leg width differ from its nominal one (a
	 *  leg_width_sigma > 0): eq. 7 then carries its normaliser along a face (alongFaceNormaliser).
	 *  Inline: asked once per contact and leg in eq. 7 (a call cost 1% of a SLAM run). */
	bool legWidthsVary() const
	{
		for (const ObjectClass& c : classes)
			if (c.leg_width_sigma > 0) return true;
		return false;
	}
	/** Largest footprint diagonal and length over the classes (search radii, hash cells). */
	double maxDiagonal() const;
	double maxLength() const;

	/** Radius gate for candidate parents: a parent is considered only when the child lies
	 *  within this distance of it (a leg's corner, a shapelet the leg's perimeter), metres. */
	double parent_gate = 0.05;

	// Negative evidence (eq. 21, ours: doc/model.md, "Free space"); optional keys
	bool free_space = false;  ///< off: the paper's model
	double free_space_p_miss = 0.05;  ///< chance a whisker sweeping through a leg misses it

	// Walls (issue 11, eqs. 22-23: doc/model.md, "Walls"); optional keys
	bool walls = false;  ///< off: no wall hypotheses (the paper's model)
	double c_W = 1e-7;  ///< wall prior density per (x, y, yaw, length) (eq. 23)
	double wall_length_scale = 5.0;  ///< lambda_W of eq. 23's exponential length prior, metres
	double wall_thickness = 0.1;  ///< thickness of every wall hypothesis (one class), metres
	/** Manhattan walls (eq. 23's yaw prior a point mass, ours: doc/model.md, "Manhattan
	 *  walls"): every wall runs along `wall_axis` or at right angles to it. */
	bool manhattan_walls = false;
	double wall_axis = 0;  ///< radians, world frame (key wall_axis_deg, degrees in [-90, 90])
	/** The direction walls are held to, if manhattan_walls (WallEvidence::fit). */
	std::optional<double> wallAxis() const { return manhattan_walls ? std::optional<double>(wall_axis) : std::nullopt; }

	/** Dimension moves (issue 11, eq. 24: doc/model.md, "Object sizes"; optional key, needs
	 *  `objects`): each table's length and width are inferred about its class's nominal ones
	 *  with the class's size_sigma; off: every table has its class's size. */
	bool size_moves = false;

	/** Reads every key of `sec` (all required but the optional shaft-noise, free-space, wall and
	 *  objects keys; `objects` is read with ObjectCatalogue::load) and calls
	 *  sec.finish(); throws core::Error. */
	static ModelParams fromIni(core::IniSection& sec);

	bool operator==(const ModelParams& o) const;
};
}  // namespace whiskermap::model
