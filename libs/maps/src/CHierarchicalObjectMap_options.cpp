// CHierarchicalObjectMap: its options, read strictly from a CMultiMetricMap .ini
// (doc/map-plugin.md), and its MRPT map definition (created by name).
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>

using whiskermap::maps::CHierarchicalObjectMap;

// Created by name from CMultiMetricMap .ini files: "hierarchicalObjectMap_count=1".
MAP_DEFINITION_REGISTER(
	"hierarchicalObjectMap,whiskermap::maps::CHierarchicalObjectMap",
	whiskermap::maps::CHierarchicalObjectMap)

namespace whiskermap::maps
{
namespace
{
/** MRPT's own keys in <prefix>_creationOpts (read by TMapGenericParams). */
constexpr const char* MRPT_GENERIC_KEYS[] = {
	"enableSaveAs3DObject", "enableObservationLikelihood", "enableObservationInsertion"};

/** Reads a section strictly when present; absent sections keep the defaults. */
template <class F>
void readSection(const mrpt::config::CConfigFileBase& c, const std::string& s, F&& read)
{
	if (!c.sectionExists(s)) return;
	whiskermap::core::IniSection sec(c, s, whiskermap::core::configLabel(c));
	read(sec);
	sec.finish();
}

const char* modeName(CHierarchicalObjectMap::TInsertionOptions::TMode m)
{
	return m == CHierarchicalObjectMap::TInsertionOptions::TMode::Lasting ? "lasting" : "per_pose";
}
}  // namespace

void CHierarchicalObjectMap::TInsertionOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	readSection(c, s, [&](core::IniSection& sec) {
		const std::string m = sec.text("mode", modeName(mode));
		if (m != "lasting" && m != "per_pose") sec.fail("mode", "'" + m + "' is not lasting or per_pose");
		mode = m == "lasting" ? TMode::Lasting : TMode::PerPose;
		lasting.visit_radius = sec.number("visit_radius", lasting.visit_radius, 0.001, 10);
		lasting.contacts_per_leg = static_cast<uint32_t>(sec.integer("contacts_per_leg", lasting.contacts_per_leg, 0, 1000));
		lasting.unexplained_per_spot =
			static_cast<uint32_t>(sec.integer("unexplained_per_spot", lasting.unexplained_per_spot, 0, 1000));
		lasting.leg_merge_gap = sec.number("leg_merge_gap", lasting.leg_merge_gap, 0, 1);
		lasting.rigid_pose = sec.boolean("rigid_pose", lasting.rigid_pose);
		lasting.noisy_revisions = static_cast<uint32_t>(sec.integer("noisy_revisions", lasting.noisy_revisions, 0, 1000));
		lasting.batch_sweeps = static_cast<uint32_t>(sec.integer("batch_sweeps", lasting.batch_sweeps, 1, 1000));
		auto& a = lasting.schedule;
		a.beta_start = sec.number("local_beta_start", a.beta_start, 1e-6, 1e6);
		a.temperatures = static_cast<uint32_t>(sec.integer("local_temperatures", a.temperatures, 1, 10000));
		a.sweeps_per_temperature =
			static_cast<uint32_t>(sec.integer("local_sweeps_per_temperature", a.sweeps_per_temperature, 1, 1000));
		a.coldest_sweeps = static_cast<uint32_t>(sec.integer("local_coldest_sweeps", a.coldest_sweeps, 1, 1000));
		a.polish_sweeps = static_cast<uint32_t>(sec.integer("local_polish_sweeps", a.polish_sweeps, 0, 1000));
		memory_size = static_cast<size_t>(sec.integer("memory_size", memory_size, 1, 1000));
		seed = static_cast<uint64_t>(sec.integer("seed", static_cast<long>(seed), 0, 1L << 53));
		use_sensor_noise = sec.boolean("use_sensor_noise", use_sensor_noise);
		keep_history = sec.boolean("keep_history", keep_history);
		swept_cell = sec.number("swept_cell", swept_cell, 0.005, 10);
		record_swept = sec.boolean("record_swept", record_swept);
		auto& m2 = consolidation;
		m2.merge_distance = sec.number("merge_distance", m2.merge_distance, 0, 100);
		m2.merge_angle = core::deg2rad(sec.number("merge_angle_deg", core::rad2deg(m2.merge_angle), 0, 90));
		m2.evidence_margin = sec.number("evidence_margin", m2.evidence_margin, 0, 10);
	});
}

void CHierarchicalObjectMap::TInsertionOptions::dumpToTextStream(std::ostream& out) const
{
	out << "mode=" << modeName(mode) << "\nvisit_radius=" << lasting.visit_radius
		<< "\ncontacts_per_leg=" << lasting.contacts_per_leg << "\nnoisy_revisions=" << lasting.noisy_revisions << "\nbatch_sweeps=" << lasting.batch_sweeps << "\nunexplained_per_spot=" << lasting.unexplained_per_spot
		<< "\nleg_merge_gap=" << lasting.leg_merge_gap
		<< "\nrigid_pose=" << lasting.rigid_pose
		<< "\nlocal_beta_start=" << lasting.schedule.beta_start << "\nlocal_temperatures=" << lasting.schedule.temperatures
		<< "\nlocal_sweeps_per_temperature=" << lasting.schedule.sweeps_per_temperature
		<< "\nlocal_coldest_sweeps=" << lasting.schedule.coldest_sweeps
		<< "\nlocal_polish_sweeps=" << lasting.schedule.polish_sweeps << "\nmemory_size=" << memory_size << "\nseed=" << seed << "\nuse_sensor_noise=" << use_sensor_noise
		<< "\nkeep_history=" << keep_history << "\nswept_cell=" << swept_cell << "\nrecord_swept=" << record_swept << "\nmerge_distance=" << consolidation.merge_distance
		<< "\nmerge_angle_deg=" << core::rad2deg(consolidation.merge_angle)
		<< "\nevidence_margin=" << consolidation.evidence_margin << "\n";
}

void CHierarchicalObjectMap::TLikelihoodOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	readSection(c, s, [&](core::IniSection& sec) {
		sweep.sigma_contact = sec.number("sigma_contact", sweep.sigma_contact, 1e-6, 10);
		sweep.sigma_normal = core::deg2rad(sec.number("sigma_normal_deg", core::rad2deg(sweep.sigma_normal), 0.01, 180));
		sweep.p_unexplained = sec.number("p_unexplained", sweep.p_unexplained, 1e-9, 1);
		sweep.p_miss = sec.number("p_miss", sweep.p_miss, 1e-9, 1);
		sweep.use_swept_grid = sec.boolean("use_swept_grid", sweep.use_swept_grid);
		sweep.cell_prior = sec.number("cell_prior", sweep.cell_prior, 1e-6, 0.999);
		sweep.cell_prior_sweeps = sec.number("cell_prior_sweeps", sweep.cell_prior_sweeps, 1e-6, 1e6);
		sweep.p_unexplored = sec.number("p_unexplored", sweep.p_unexplored, 1e-12, 1);
		min_existence = sec.number("min_existence", min_existence, 0, 1);
		min_support = static_cast<uint32_t>(sec.integer("min_support", min_support, 0, 1000000));
		wall_extension = sec.number("wall_extension", wall_extension, 0, 100);
		wall_extension_min_length = sec.number("wall_extension_min_length", wall_extension_min_length, 0, 100);
		disjoint_tables = sec.boolean("disjoint_tables", disjoint_tables);
	});
}

void CHierarchicalObjectMap::TLikelihoodOptions::dumpToTextStream(std::ostream& out) const
{
	out << "sigma_contact=" << sweep.sigma_contact << "\nsigma_normal_deg=" << core::rad2deg(sweep.sigma_normal)
		<< "\np_unexplained=" << sweep.p_unexplained << "\np_miss=" << sweep.p_miss
		<< "\nuse_swept_grid=" << sweep.use_swept_grid << "\ncell_prior=" << sweep.cell_prior
		<< "\ncell_prior_sweeps=" << sweep.cell_prior_sweeps << "\np_unexplored=" << sweep.p_unexplored
		<< "\nmin_existence=" << min_existence << "\nmin_support=" << min_support << "\nwall_extension=" << wall_extension
		<< "\nwall_extension_min_length=" << wall_extension_min_length << "\ndisjoint_tables=" << disjoint_tables << "\n";
}

CHierarchicalObjectMap::TMapDefinition::TMapDefinition() = default;

void CHierarchicalObjectMap::TMapDefinition::loadFromConfigFile_map_specific(
	const mrpt::config::CConfigFileBase& c, const std::string& prefix)
{
	readSection(c, prefix + "_creationOpts", [&](core::IniSection& sec) {
		for (const char* k : MRPT_GENERIC_KEYS) sec.boolean(k, true);  // MRPT reads these
		auto& r = renderOptions;
		r.table_height = sec.number("table_height", r.table_height, 0.01, 10);
		r.top_thickness = sec.number("top_thickness", r.top_thickness, 0.001, r.table_height);
		r.octomap_resolution = sec.number("octomap_resolution", r.octomap_resolution, 0.001, 1);
	});
	insertionOptions.loadFromConfigFile(c, prefix + "_insertOpts");
	likelihoodOptions.loadFromConfigFile(c, prefix + "_likelihoodOpts");
	readSection(c, prefix + "_model", [&](core::IniSection& sec) {
		modelParams = model::ModelParams::fromIni(sec);
	});
	readSection(c, prefix + "_sampler", [&](core::IniSection& sec) {
		samplerParams = inference::SamplerParams::fromIni(sec);
	});
	if (!insertionOptions.record_swept && sweptGridRead())
		throw core::Error(
			core::configLabel(c) + ": [" + prefix + "_insertOpts]: record_swept = false leaves the swept grid empty, but " +
			(modelParams.free_space ? "the model's free_space" : "the likelihood's use_swept_grid") + " reads it");
	// A misspelt section name would otherwise be ignored silently.
	std::vector<std::string> sections;
	c.getAllSections(sections);
	for (const auto& s : sections)
	{
		if (s.rfind(prefix + "_", 0) != 0) continue;
		const std::string suffix = s.substr(prefix.size() + 1);
		if (suffix != "creationOpts" && suffix != "insertOpts" && suffix != "likelihoodOpts" &&
			suffix != "model" && suffix != "sampler")
			throw core::Error(core::configLabel(c) + ": [" + s + "]: unknown section");
	}
}

void CHierarchicalObjectMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const
{
	out << "table_height=" << renderOptions.table_height << "\ntop_thickness=" << renderOptions.top_thickness
		<< "\noctomap_resolution=" << renderOptions.octomap_resolution << "\n";
	insertionOptions.dumpToTextStream(out);
	likelihoodOptions.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CHierarchicalObjectMap::internal_CreateFromMapDefinition(
	const mrpt::maps::TMetricMapInitializer& _def)
{
	const auto& def = dynamic_cast<const TMapDefinition&>(_def);
	auto* m = new CHierarchicalObjectMap();
	m->insertionOptions = def.insertionOptions;
	m->likelihoodOptions = def.likelihoodOptions;
	m->renderOptions = def.renderOptions;
	m->modelParams = def.modelParams;
	m->samplerParams = def.samplerParams;
	return m;
}
}  // namespace whiskermap::maps
