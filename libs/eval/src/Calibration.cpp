#include <whiskermap/core/Error.h>
#include <whiskermap/eval/Calibration.h>
#include <whiskermap/eval/MapEvaluation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "JsonNumber.h"

namespace whiskermap::eval
{
using detail::num;

double Calibration::Bin::meanExistence() const { return count ? sumExistence / count : NAN; }
double Calibration::Bin::fractionReal() const { return count ? static_cast<double>(real) / count : NAN; }

void Calibration::add(double existence, bool real)
{
	if (!(existence >= 0 && existence <= 1))
		throw core::Error("calibration: existence " + std::to_string(existence) + " is not in [0, 1]");
	auto& b = m_bins[std::min(static_cast<size_t>(existence * BINS), BINS - 1)];
	b.count++;
	b.sumExistence += existence;
	b.real += real ? 1 : 0;
}

void Calibration::add(const Calibration& other)
{
	for (size_t i = 0; i < BINS; i++)
	{
		m_bins[i].count += other.m_bins[i].count;
		m_bins[i].sumExistence += other.m_bins[i].sumExistence;
		m_bins[i].real += other.m_bins[i].real;
	}
}

Calibration Calibration::of(
	const std::vector<world::Table>& truth, const std::vector<TableCsv::MapRow>& objects,
	const EvalOptions& opts, bool hasClass)
{
	const auto m = MapEvaluation::compute(truth, TableCsv::tables(objects), opts, hasClass);
	std::vector<bool> real(objects.size(), false);
	for (int j : m.truthMatch)
		if (j >= 0) real[j] = true;
	Calibration c;
	for (size_t i = 0; i < objects.size(); i++) c.add(objects[i].existence, real[i]);
	return c;
}

size_t Calibration::count() const
{
	size_t n = 0;
	for (const auto& b : m_bins) n += b.count;
	return n;
}

size_t Calibration::real() const
{
	size_t n = 0;
	for (const auto& b : m_bins) n += b.real;
	return n;
}

double Calibration::ece() const
{
	const size_t n = count();
	if (n == 0) return NAN;
	double e = 0;
	for (const auto& b : m_bins)  // ECE = sum_b (n_b / N) |real_b - conf_b|
		if (b.count) e += static_cast<double>(b.count) / n * std::abs(b.fractionReal() - b.meanExistence());
	return e;
}

std::string Calibration::toJson(int indent) const
{
	const std::string pad(indent + 2, ' '), pad2(indent + 4, ' ');
	std::string s = "{\n" + pad + "\"objects\": " + std::to_string(count()) + ",\n" + pad +
					"\"real\": " + std::to_string(real()) + ",\n" + pad + "\"ece\": " + num(ece()) +
					",\n" + pad + "\"bins\": [\n";
	for (size_t i = 0; i < BINS; i++)
	{
		const auto& b = m_bins[i];
		s += pad2 + "{\"lo\": " + num(static_cast<double>(i) / BINS) + ", \"hi\": " +
			 num(static_cast<double>(i + 1) / BINS) + ", \"count\": " + std::to_string(b.count) +
			 ", \"real\": " + std::to_string(b.real) + ", \"mean_existence\": " + num(b.meanExistence()) +
			 ", \"fraction_real\": " + num(b.fractionReal()) + "}" + (i + 1 < BINS ? ",\n" : "\n");
	}
	return s + pad + "]\n" + std::string(indent, ' ') + "}";
}

std::string Calibration::toText() const
{
	char buf[160];
	std::snprintf(
		buf, sizeof(buf), "calibration: %zu objects, %zu real; ECE %s\n%-11s %7s %7s %15s %14s\n",
		count(), real(), num(ece()).c_str(), "existence", "objects", "real", "mean existence", "fraction real");
	std::string s = buf;
	for (size_t i = 0; i < BINS; i++)
	{
		const auto& b = m_bins[i];
		std::snprintf(
			buf, sizeof(buf), "[%.1f, %.1f%c %7zu %7zu %15s %14s\n", static_cast<double>(i) / BINS,
			static_cast<double>(i + 1) / BINS, i + 1 < BINS ? ')' : ']', b.count, b.real,
			b.count ? num(b.meanExistence()).c_str() : "-", b.count ? num(b.fractionReal()).c_str() : "-");
		s += buf;
	}
	return s;
}
}  // namespace whiskermap::eval
