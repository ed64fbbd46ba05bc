#include <whiskermap/inference/ExactMapOracle.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Factors.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace whiskermap::inference
{
using model::Leg;
using model::ModelParams;
using model::Table;

namespace
{
constexpr double NEG_INF = -std::numeric_limits<double>::infinity();
constexpr size_t MAX_SHAPELETS = 8;  ///< masks are uint32_t; 3^8 subset pairs stay cheap

/** Best overlap-free gain of one table's completions that explain exactly `mask`: the
 *  table's own terms plus its linked legs, over "every shapelet uncaused". `here` counts
 *  legs at the corner being added (complete() scratch). */
struct Completion
{
	uint32_t mask;
	double gain;
	int here;
};

/** One way to explain a group of shapelets: a leg, free (table -1) or at a table corner. */
struct Option
{
	uint32_t mask;
	double gain;  ///< as legGain()
	Leg leg;
	int table, corner;
};

/** A subset of shapelets that one leg could explain, and its best pose as a free leg. */
struct Group
{
	uint32_t mask;
	Leg free;
	double freeGain;
};

/** A table that beats free legs on the shapelets `mask` by `gain` (a possible second table). */
struct Helper
{
	double gain;
	int32_t table;
	uint32_t mask;
};

/** A candidate table set ranked by its overlap-free completion gain (an upper bound of its
 *  logJoint minus the baseline). */
struct Candidate
{
	double bound;
	int32_t a, b;  ///< indices into Search::m_tables, -1 for none
};

double sq(double v) { return v * v; }

/** One solve(): the problem's shapelets, its leg groups and the enumerated tables. */
class Search
{
   public:
	Search(const ModelParams& p, const OracleOptions& o, const std::vector<obs::Shapelet>& s)
		: m_p(p), m_o(o), m_s(s), m_full((1u << s.size()) - 1), m_bb(p)
	{
		m_reach = 2 * p.parent_gate + p.leg_width / std::sqrt(2.0);
		const Table t{0, 0, 0, p.leg_width, p.texture};
		m_emptyCorner = std::max(inventedCell(t, 0), model::logMissingLegs(1, p));
		m_inventLegs = m_emptyCorner > model::logMissingLegs(1, p);
		m_tableCell = model::logCell(model::logTablePrior(p), p);
	}

	OracleResult run()
	{
		m_slot.assign(m_full + 1, -1);
		makeGroups();
		freeLegs();
		Candidate none{m_fb[m_full], -1, -1};
		m_result.configurationsScored++;
		verify({none});
		if (m_o.max_tables >= 1 && m_s.size() >= 2) enumerateTables();
		m_result.logPosterior = m_best;
		return m_result;
	}

   private:
	// ---- legs ---------------------------------------------------------------------------

	/** Gain of leg `l` explaining the shapelets of `mask`, linked to corner `corner` of `t`
	 *  (or free if t == nullptr), over those shapelets uncaused: eq. 19 cell of eq. 12 with
	 *  eqs. 5-6, 8, plus eq. 12 with eqs. 7, 9 per shapelet. -inf outside the parent gate. */
	double legGain(uint32_t mask, const Leg& l, const Table* t, int corner) const
	{
		double cause = NEG_INF;
		if (t)
		{
			double cx = 0, cy = 0;
			model::tableCorner(*t, corner, m_p, cx, cy);
			if (sq(cx - l.x) + sq(cy - l.y) > sq(m_p.parent_gate)) return NEG_INF;
			const model::LegFit fit = model::logLegGivenTable(l, *t, m_p);
			if (fit.corner != corner) return NEG_INF;
			cause = fit.logDensity;
		}
		double gain = model::logCell(model::logNoisyOr(cause, model::logLegNull(m_p)), m_p);
		const model::OrientedRect r = model::legRect(l);
		const double null = model::logShapeletNull(m_p);
		for (size_t i = 0; i < m_s.size(); i++)
		{
			if (!(mask >> i & 1)) continue;
			if (r.perimeter(m_s[i].x, m_s[i].y).distance > m_p.parent_gate) return NEG_INF;
			gain += model::logNoisyOr(model::logShapeletGivenLeg(m_s[i], l, m_p), null) - null;
		}
		return gain;
	}

	/** A square leg at (x, y, theta) with the shared side and texture. */
	Leg leg(double x, double y, double theta, double texture) const
	{
		Leg l;
		l.x = x;
		l.y = y;
		l.theta = theta;
		l.wx = l.wy = m_p.leg_width;
		l.texture = texture;
		return l;
	}

	/** Minimiser of the quadratic part of eqs. 6-7 for a leg explaining `mask`, each contact
	 *  on the face whose normal matches its own: yaw = mean of the normals' (and the table's)
	 *  yaws modulo 90 deg; centre = least squares of "each contact on its face line" and
	 *  "near (qx, qy)" with weight `pull` (a table corner: ModelParams::cornerPull; tiny for a free leg:
	 *  it only fixes the position along a face), then moved so each contact lies on its face
	 *  rather than beyond it. */
	Leg closedForm(uint32_t mask, const Table* t, double qx, double qy, double pull) const
	{
		const obs::Shapelet* members[MAX_SHAPELETS];
		size_t n = 0;
		for (size_t i = 0; i < m_s.size(); i++)
			if (mask >> i & 1) members[n++] = &m_s[i];
		return fitLeg(m_p, members, n, t, qx, qy, pull);
	}

	/** Best free leg for `mask`: compass search on (x, y, theta), down to 0.1 mm and 0.001
	 *  rad, from the closed form and from the sampler's placement of each member (contact
	 *  centred on the face of matching normal). */
	Group fitFree(uint32_t mask) const
	{
		constexpr double WEAK = 1e-3;  // only breaks the along-face degeneracy
		Group g{mask, Leg{}, NEG_INF};
		double cx = 0, cy = 0, n = 0;
		for (size_t i = 0; i < m_s.size(); i++)
			if (mask >> i & 1)
				cx += m_s[i].x - std::cos(m_s[i].normal) * m_p.leg_width / 2,
					cy += m_s[i].y - std::sin(m_s[i].normal) * m_p.leg_width / 2, n++;
		std::vector<Leg> seeds{closedForm(mask, nullptr, cx / n, cy / n, WEAK)};
		for (size_t i = 0; i < m_s.size(); i++)
			if (mask >> i & 1) seeds.push_back(closedForm(1u << i, nullptr, 0, 0, WEAK));
		for (Leg l : seeds)
		{
			l.texture = seeds[0].texture;
			const double best = compassSearch(
				l, m_p.leg_width, legGain(mask, l, nullptr, -1), 1e-12,
				[&](const Leg& c) { return legGain(mask, c, nullptr, -1); });
			if (best > g.freeGain) g.free = l, g.freeGain = best;
		}
		return g;
	}

	/** Best leg for group `g` at corner `corner` of `t`: the closed form pulled to the corner,
	 *  or the group's free pose if better. */
	double fitLinked(const Group& g, const Table& t, int corner, Leg& out) const
	{
		double qx = 0, qy = 0;
		model::tableCorner(t, corner, m_p, qx, qy);
		out = closedForm(g.mask, &t, qx, qy, m_p.cornerPull());
		double best = legGain(g.mask, out, &t, corner);
		if (sq(g.free.x - qx) + sq(g.free.y - qy) > sq(m_p.parent_gate)) return best;
		Leg alt = g.free;
		alt.texture = out.texture;
		const double v = legGain(g.mask, alt, &t, corner);
		if (v > best) best = v, out = alt;
		return best;
	}

	// ---- groups and free legs -------------------------------------------------------------

	void makeGroups()
	{
		const double span = 2 * (m_p.leg_width / std::sqrt(2.0) + m_p.parent_gate);
		for (uint32_t mask = 1; mask <= m_full; mask++)
		{
			bool close = true;
			for (size_t i = 0; i < m_s.size() && close; i++)
				for (size_t j = i + 1; j < m_s.size() && close; j++)
					close = !((mask >> i & 1) && (mask >> j & 1)) ||
							std::hypot(m_s[i].x - m_s[j].x, m_s[i].y - m_s[j].y) <= span;
			if (!close) continue;
			const Group g = fitFree(mask);
			if (g.freeGain > NEG_INF) m_groups.push_back(g);
		}
	}

	/** m_fb[r]: best gain of free legs explaining some of the shapelets in r (the others
	 *  uncaused): exact over partitions of r into groups (eqs. 8, 12). */
	void freeLegs()
	{
		m_fb.assign(m_full + 1, 0);
		for (uint32_t r = 1; r <= m_full; r++)
		{
			const uint32_t low = r & (~r + 1);
			m_fb[r] = m_fb[r & ~low];  // the lowest shapelet uncaused
			for (const Group& g : m_groups)
				if ((g.mask & low) && (g.mask & r) == g.mask) m_fb[r] = std::max(m_fb[r], g.freeGain + m_fb[r & ~g.mask]);
		}
	}

	// ---- one table ------------------------------------------------------------------------

	/** Fills m_completions with the best completion of table t per explained set: corners
	 *  one by one, each with no leg (invented or missing: eq. 15) or any number of legs of
	 *  disjoint groups (eq. 17 per pair). Only groups whose members are all within reach of
	 *  the corner can link there. */
	void complete(const Table& t)
	{
		m_completions.assign(1, Completion{0, m_tableCell, 0});
		for (int c = 0; c < 4; c++)
		{
			double qx = 0, qy = 0;
			model::tableCorner(t, c, m_p, qx, qy);
			uint32_t near = 0;
			for (size_t i = 0; i < m_s.size(); i++)
				near |= static_cast<uint32_t>(sq(m_s[i].x - qx) + sq(m_s[i].y - qy) <= sq(m_reach)) << i;
			m_options.clear();
			for (size_t k = 0; k < m_groups.size() && near; k++)
			{
				if ((m_groups[k].mask & near) != m_groups[k].mask) continue;
				Leg l;
				const double gain = fitLinked(m_groups[k], t, c, l);
				if (gain > NEG_INF) m_options.push_back({m_groups[k].mask, gain, 0});
			}
			m_next.clear();
			for (const Completion& state : m_completions)
			{
				m_chain.assign(1, {state.mask, state.gain, 0});
				for (const Completion& o : m_options)
					for (size_t e = 0, n = m_chain.size(); e < n; e++)
						if (!(m_chain[e].mask & o.mask))
							m_chain.push_back({m_chain[e].mask | o.mask,
											   m_chain[e].gain + o.gain + model::logSameCorner(m_chain[e].here, m_p),
											   m_chain[e].here + 1});
				m_chain[0].gain += m_emptyCorner;
				for (const Completion& e : m_chain)
				{
					int32_t& slot = m_slot[e.mask];
					if (slot < 0)
					{
						slot = static_cast<int32_t>(m_next.size());
						m_next.push_back({e.mask, e.gain, 0});
					}
					else
						m_next[slot].gain = std::max(m_next[slot].gain, e.gain);
				}
			}
			for (const Completion& e : m_next) m_slot[e.mask] = -1;
			m_completions.swap(m_next);
		}
	}

	// ---- the grid of tables ------------------------------------------------------------------

	/** Every grid table with at least two corners within reach of a shapelet (doc/oracle.md:
	 *  tables with shapelet-explaining legs at one corner only never pay off). */
	void enumerateTables()
	{
		const double h = m_o.grid_step, margin = m_reach + std::hypot(m_p.table_length, m_p.table_width) / 2;
		double x0 = m_s[0].x, x1 = x0, y0 = m_s[0].y, y1 = y0;
		for (const obs::Shapelet& s : m_s)
			x0 = std::min(x0, s.x), x1 = std::max(x1, s.x), y0 = std::min(y0, s.y), y1 = std::max(y1, s.y);
		const auto i0 = static_cast<int64_t>(std::floor((x0 - margin) / h));
		const auto j0 = static_cast<int64_t>(std::floor((y0 - margin) / h));
		const auto ni = static_cast<int64_t>(std::ceil((x1 + margin) / h)) - i0 + 1;
		const auto nj = static_cast<int64_t>(std::ceil((y1 + margin) / h)) - j0 + 1;
		const auto yaws = static_cast<int>(std::ceil(M_PI / m_o.yaw_step - 1e-9));
		std::vector<uint8_t> marks(static_cast<size_t>(ni * nj));
		std::vector<size_t> cells;
		std::vector<Candidate> singles;
		for (int k = 0; k < yaws; k++)
		{
			Table t{0, 0, k * m_o.yaw_step, m_p.leg_width, m_p.texture};
			std::fill(marks.begin(), marks.end(), 0);
			cells.clear();
			for (int c = 0; c < 4; c++)
			{
				double ox = 0, oy = 0;
				model::tableCorner(t, c, m_p, ox, oy);
				for (const obs::Shapelet& s : m_s)
				{
					const double cx = s.x - ox, cy = s.y - oy;
					for (auto i = static_cast<int64_t>(std::ceil((cx - m_reach) / h)); i * h <= cx + m_reach; i++)
						for (auto j = static_cast<int64_t>(std::ceil((cy - m_reach) / h)); j * h <= cy + m_reach; j++)
						{
							if (sq(i * h - cx) + sq(j * h - cy) > sq(m_reach)) continue;
							uint8_t& m = marks[static_cast<size_t>((i - i0) * nj + (j - j0))];
							if (m & (1 << c)) continue;
							if (m && !(m & (m - 1))) cells.push_back(static_cast<size_t>((i - i0) * nj + (j - j0)));
							m |= static_cast<uint8_t>(1 << c);
						}
				}
			}
			for (const size_t cell : cells)
			{
				t.x = (static_cast<int64_t>(cell) / nj + i0) * h;
				t.y = (static_cast<int64_t>(cell) % nj + j0) * h;
				scoreTable(t, singles);
			}
		}
		verify(singles);
		if (m_o.max_tables >= 2) pairs();
	}

	/** Completes table t; keeps it as a single candidate if it may beat the best so far, and
	 *  its completions if it can help a second table (gain over free legs > 0). */
	void scoreTable(const Table& t, std::vector<Candidate>& singles)
	{
		complete(t);
		m_result.configurationsScored++;
		double best = NEG_INF, help = NEG_INF;
		for (const Completion& c : m_completions)
		{
			best = std::max(best, c.gain + m_fb[m_full & ~c.mask]);
			help = std::max(help, c.gain - m_fb[c.mask]);
		}
		if (best + baseline() <= m_best && help <= 0) return;
		const auto id = static_cast<int32_t>(m_tables.size());
		m_tables.push_back(t);
		if (best + baseline() > m_best) singles.push_back({best, id, -1});
		if (help <= 0) return;
		for (const Completion& c : m_completions)
			if (c.gain - m_fb[c.mask] > 0) m_helpers.push_back({c.gain - m_fb[c.mask], id, c.mask});
	}

	double baseline() const { return static_cast<double>(m_s.size()) * model::logShapeletNull(m_p); }

	/** Pairs of tables: a second table adds at most its best gain over free legs on shapelets
	 *  the first leaves (bound), so only pairs whose bound beats the best are completed. */
	void pairs()
	{
		std::sort(m_helpers.begin(), m_helpers.end(), [](const Helper& a, const Helper& b) { return a.gain > b.gain; });
		std::vector<double> sub(m_full + 1, NEG_INF);  // best helper gain on a subset of r
		std::vector<int32_t> firsts;
		for (const Helper& h : m_helpers)
		{
			sub[h.mask] = std::max(sub[h.mask], h.gain);
			firsts.push_back(h.table);
		}
		for (size_t i = 0; i < m_s.size(); i++)
			for (uint32_t r = 0; r <= m_full; r++)
				if (r >> i & 1) sub[r] = std::max(sub[r], sub[r & ~(1u << i)]);
		std::sort(firsts.begin(), firsts.end());
		firsts.erase(std::unique(firsts.begin(), firsts.end()), firsts.end());
		std::unordered_map<uint64_t, double> found;  // (first, second) -> best gain
		for (const int32_t a : firsts)
		{
			complete(m_tables[a]);
			for (const Completion& c1 : m_completions)
			{
				const uint32_t rest = m_full & ~c1.mask;
				const double need = m_best - baseline() - c1.gain - m_fb[rest];
				if (sub[rest] <= need) continue;
				for (const Helper& h2 : m_helpers)
				{
					if (h2.gain <= need) break;
					if (h2.table <= a || (h2.mask & c1.mask)) continue;
					const double gain = c1.gain + h2.gain + m_fb[h2.mask] + m_fb[rest & ~h2.mask] + tablesOverlap(a, h2.table);
					double& f = found.try_emplace(static_cast<uint64_t>(a) << 32 | static_cast<uint32_t>(h2.table), NEG_INF).first->second;
					f = std::max(f, gain);
				}
			}
		}
		std::vector<Candidate> candidates;
		for (const auto& [key, gain] : found)
			candidates.push_back({gain, static_cast<int32_t>(key >> 32), static_cast<int32_t>(key & 0xffffffffu)});
		m_result.configurationsScored += found.size();
		verify(candidates);
	}

	double tablesOverlap(int32_t a, int32_t b) const
	{
		return model::tableRect(m_tables[a], m_p).overlaps(model::tableRect(m_tables[b], m_p)) ? model::logOverlap(1, m_p) : 0;
	}

	// ---- verification with logJoint --------------------------------------------------------

	/** Best first: solves each candidate table set exactly (solveTables) until the next
	 *  overlap-free bound cannot beat the best score. */
	void verify(std::vector<Candidate> candidates)
	{
		std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.bound > b.bound; });
		for (const Candidate& c : candidates)
		{
			if (c.bound + baseline() <= m_best) break;
			solveTables(c);
		}
	}

	/** Exact best completion of the tables of c, overlaps (eq. 16) included: branch and bound
	 *  over the shapelets in order, each uncaused or the lowest member of a group explained by
	 *  a free leg or a leg at a table corner; the bound is the overlap-free optimum of the
	 *  rest. The best board is rebuilt and scored by logJoint. */
	void solveTables(const Candidate& c)
	{
		m_set.clear();
		for (const int32_t i : {c.a, c.b})
			if (i >= 0) m_set.push_back(m_tables[i]);
		m_opts.clear();
		for (const Group& g : m_groups)
		{
			addWithSlides({g.mask, g.freeGain, g.free, -1, -1});
			for (size_t t = 0; t < m_set.size(); t++)
				for (int corner = 0; corner < 4; corner++)
				{
					Option o{g.mask, 0, Leg{}, static_cast<int>(t), corner};
					o.gain = fitLinked(g, m_set[t], corner, o.leg);
					if (o.gain > NEG_INF) addWithSlides(o);
				}
		}
		// Overlap-free bound of explaining r; a leg at a corner may also spare an empty corner.
		m_ub.assign(m_full + 1, 0);
		for (uint32_t r = 1; r <= m_full; r++)
		{
			const uint32_t low = r & (~r + 1);
			m_ub[r] = m_ub[r & ~low];
			for (const Option& o : m_opts)
				if ((o.mask & low) && (o.mask & r) == o.mask)
					m_ub[r] = std::max(m_ub[r], o.gain - (o.table >= 0 ? m_emptyCorner : 0) + m_ub[r & ~o.mask]);
		}
		double value = baseline() + (m_set.size() == 2 ? tablesOverlap(c.a, c.b) : 0);
		for (size_t t = 0; t < m_set.size(); t++) value += m_tableCell + 4 * m_emptyCorner;
		m_counts.assign(4 * m_set.size(), 0);
		m_placed.clear();
		m_localBest = m_best;
		branch(m_full, value);
		m_result.configurationsScored++;
		if (m_localBest == m_best) return;  // nothing better than the best so far
		double lp = build();
		m_result.boardsScored++;
		if (std::abs(lp - m_localBest) > 1e-6) m_result.certified = false;
		lp = polishLegs(lp);
		if (lp > m_best)
		{
			m_best = lp;
			m_result.map = m_bb.compact();
		}
	}

	/** Adds option o and the same leg slid along its contacts' face to either end of the
	 *  range that keeps every contact on its face: contacts on one face leave the leg free
	 *  along it (nearly the same gain), and a slid leg may avoid an overlap (eq. 16) that the
	 *  optimal pose would pay. Faces are those of closedForm(); a contact on an adjacent face
	 *  pins the leg (no slides). */
	void addWithSlides(const Option& o)
	{
		m_opts.push_back(o);
		const double w = m_p.leg_width;
		double lo = -w, hi = w, tx = 0, ty = 0;
		bool first = true;
		for (size_t i = 0; i < m_s.size(); i++)
		{
			if (!(o.mask >> i & 1)) continue;
			const double f = m_s[i].normal - core::angleDiff(m_s[i].normal, o.leg.theta, M_PI_2);
			if (first) tx = -std::sin(f), ty = std::cos(f), first = false;
			if (std::abs(tx * std::cos(f) + ty * std::sin(f)) > 0.5) return;  // adjacent face
			const double a = tx * (m_s[i].x - o.leg.x) + ty * (m_s[i].y - o.leg.y);
			lo = std::max(lo, a - w / 2), hi = std::min(hi, a + w / 2);
		}
		// Just inside either end: a contact exactly at a corner may take the adjacent face.
		constexpr double INSIDE = 1e-3;
		for (const double shift : {lo + INSIDE, hi - INSIDE})
		{
			if (std::abs(shift) < 1e-3) continue;
			Option slid = o;
			slid.leg.x += tx * shift, slid.leg.y += ty * shift;
			slid.gain = legGain(o.mask, slid.leg, o.table >= 0 ? &m_set[o.table] : nullptr, o.corner);
			if (slid.gain > NEG_INF) m_opts.push_back(slid);
		}
	}

	void branch(uint32_t rest, double value)
	{
		if (value + m_ub[rest] <= m_localBest) return;
		if (!rest)
		{
			std::vector<int> invent;
			value += inventLegs(invent);
			if (value > m_localBest) m_localBest = value, m_bestPlaced = m_placed, m_bestInvented = invent;
			return;
		}
		const uint32_t low = rest & (~rest + 1);
		branch(rest & ~low, value);  // the lowest shapelet uncaused
		for (size_t k = 0; k < m_opts.size(); k++)
		{
			const Option o = m_opts[k];  // a copy: the recursion below appends to m_opts
			if (!(o.mask & low) || (o.mask & rest) != o.mask) continue;
			double v = value + o.gain + model::logOverlap(overlaps(o.leg), m_p);
			if (o.table >= 0)
			{
				const int n = m_counts[4 * o.table + o.corner]++;
				v += n == 0 ? -m_emptyCorner : model::logSameCorner(n, m_p);
			}
			m_placed.push_back(static_cast<int>(k));
			branch(rest & ~o.mask, v);
			m_placed.pop_back();
			if (o.table >= 0) m_counts[4 * o.table + o.corner]--;
		}
	}

	/** Legs of m_placed overlapping `l`. */
	int overlaps(const Leg& l) const
	{
		const model::OrientedRect r = model::legRect(l);
		int n = 0;
		for (const int k : m_placed) n += r.overlaps(model::legRect(m_opts[k].leg));
		return n;
	}

	/** Empty corners: an invented leg (with its overlaps) or a missing one, whichever is
	 *  better, corner by corner; returns the change from the m_emptyCorner charged. */
	double inventLegs(std::vector<int>& invent)
	{
		double change = 0;
		const size_t placed = m_placed.size();
		for (size_t i = 0; i < 4 * m_set.size(); i++)
		{
			if (m_counts[i] || !m_inventLegs) continue;
			const Leg l = cornerLeg(m_set[i / 4], static_cast<int>(i % 4));
			const double v = inventedCell(m_set[i / 4], static_cast<int>(i % 4)) + model::logOverlap(overlaps(l), m_p);
			if (v <= model::logMissingLegs(1, m_p))
			{
				change += model::logMissingLegs(1, m_p) - m_emptyCorner;
				continue;
			}
			change += v - m_emptyCorner;
			invent.push_back(static_cast<int>(i));
			m_opts.push_back({0, 0, l, -1, -1});  // so later invented legs see it
			m_placed.push_back(static_cast<int>(m_opts.size() - 1));
		}
		m_placed.resize(placed);
		for (size_t k = 0; k < invent.size(); k++) m_opts.pop_back();
		return change;
	}

	/** The leg a table expects at `corner` (exactly there, its yaw and texture). */
	Leg cornerLeg(const Table& t, int corner) const
	{
		Leg l = leg(0, 0, t.theta, t.texture);
		model::tableCorner(t, corner, m_p, l.x, l.y);
		return l;
	}

	/** eq. 19 cell of that leg's eq. 12 density (eqs. 5-6 at Delta = 0, or'ed with eq. 8). */
	double inventedCell(const Table& t, int corner) const
	{
		const double cause = model::logLegGivenTable(cornerLeg(t, corner), t, m_p).logDensity;
		return model::logCell(model::logNoisyOr(cause, model::logLegNull(m_p)), m_p);
	}

	/** The best completion found by branch() on m_bb; its logJoint. */
	double build()
	{
		m_bb.reset(m_s);
		std::vector<model::Id> ids;
		for (const Table& t : m_set) ids.push_back(m_bb.addTable(t));
		for (const int k : m_bestPlaced)
		{
			Leg l = m_opts[k].leg;
			l.parent = m_opts[k].table >= 0 ? ids[m_opts[k].table] : model::NONE;
			const model::Id id = m_bb.addLeg(l);
			for (size_t i = 0; i < m_s.size(); i++)
				if (m_opts[k].mask >> i & 1) m_bb.setShapeletParent(i, id);
		}
		for (const int i : m_bestInvented)
		{
			Leg l = cornerLeg(m_set[i / 4], i % 4);
			l.parent = ids[i / 4];
			m_bb.addLeg(l);
		}
		return model::logJoint(m_bb);
	}

	/** Compass search of each leg's pose of the rebuilt board on its exact local log-odds
	 *  (eq. 20): eq. 7 counts the distance past a face's end, which the options' closed-form
	 *  poses do not see. Returns the board's logJoint after it. */
	double polishLegs(double lp)
	{
		for (model::Id l = 0; l < m_bb.legIdBound(); l++) lp += searchLegPose(m_bb, l, 1e-12);
		return lp;
	}

	const ModelParams& m_p;
	const OracleOptions& m_o;
	const std::vector<obs::Shapelet>& m_s;
	const uint32_t m_full;
	double m_reach = 0, m_emptyCorner = 0, m_tableCell = 0;
	bool m_inventLegs = true;

	std::vector<Group> m_groups;
	std::vector<double> m_fb;
	std::vector<Table> m_tables;
	std::vector<Helper> m_helpers;  ///< completions that beat free legs, best first (pairs)

	// complete() scratch and output
	std::vector<Completion> m_next, m_chain, m_options, m_completions;
	std::vector<int32_t> m_slot;  ///< index in m_next per mask, -1 if none

	// solveTables() state
	std::vector<Table> m_set;
	std::vector<Option> m_opts;
	std::vector<double> m_ub;
	std::vector<int> m_counts, m_placed, m_bestPlaced, m_bestInvented;
	double m_localBest = NEG_INF;

	model::Blackboard m_bb;
	double m_best = NEG_INF;
	OracleResult m_result;
};
}  // namespace

ExactMapOracle::ExactMapOracle(const ModelParams& model, const OracleOptions& options)
	: m_model(model), m_options(options)
{
	if (!(options.grid_step > 0) || !(options.yaw_step > 0) || options.max_tables < 0 || options.max_tables > 2 ||
		options.max_shapelets > MAX_SHAPELETS)
		throw std::invalid_argument("ExactMapOracle: grid_step, yaw_step > 0; max_tables 0..2; max_shapelets <= 8");
	// A table whose shapelet-explaining legs sit at one corner only must lose to the same legs
	// without it (doc/oracle.md): its cell, the other three corners at best, and each extra
	// leg at that corner either >= w/2 from it (non-overlapping) or overlapping the first.
	const Table t{0, 0, 0, model.leg_width, model.texture};
	const auto linkGain = [&](double d) {
		Leg l;
		model::tableCorner(t, 0, model, l.x, l.y);
		l.x += d;
		l.wx = l.wy = model.leg_width;
		l.texture = model.texture;
		return model::logNoisyOr(model::logLegGivenTable(l, t, model).logDensity, model::logLegNull(model)) -
			   model::logLegNull(model);
	};
	const double extra = std::max(linkGain(model.leg_width / 2), linkGain(0) + model::logOverlap(1, model));
	const double empty = std::max(model::logCell(linkGain(0) + model::logLegNull(model), model), model::logMissingLegs(1, model));
	for (size_t k = 1; k <= options.max_shapelets; k++)
		if (model::logCell(model::logTablePrior(model), model) + linkGain(0) + (k - 1.0) * extra +
				model::logSameCorner(static_cast<int>(k * (k - 1) / 2), model) + 3 * empty >= 0)
			throw std::invalid_argument("ExactMapOracle: model parameters let a one-corner table pay off");
}

OracleResult ExactMapOracle::solve(const std::vector<obs::Shapelet>& shapelets) const
{
	if (shapelets.size() > m_options.max_shapelets)
		throw std::invalid_argument("ExactMapOracle: more shapelets than max_shapelets");
	return Search(m_model, m_options, shapelets).run();
}
}  // namespace whiskermap::inference
