#include <whiskermap/core/Error.h>
#include <whiskermap/world/ContactLogFormat.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>

namespace whiskermap::world
{
namespace
{
static_assert(
	std::numeric_limits<long double>::digits >= 64,
	"exact degree conversions need a long double wider than double (x86-64, arm64 Linux)");

constexpr long double DEG_PER_RAD = 57.295779513082320876798154814105170332405472466564L;
constexpr long double RAD_PER_DEG = 0.017453292519943295769236907684886127134428718885417L;
constexpr int64_t TICKS_PER_SECOND = 10000000;					   // mrpt::Clock: 100 ns ticks
constexpr int64_t UNIX_EPOCH_TICKS = INT64_C(116444736000000000);  // 1970 in ticks since 1601
constexpr int MAX_DIGITS = 19;	// significant digits that fit a uint64_t

/** Powers of ten that long double holds exactly (5^27 < 2^64). */
constexpr int EXACT_POW10 = 27;
constexpr std::array<long double, EXACT_POW10 + 1> powersOfTen()
{
	std::array<long double, EXACT_POW10 + 1> p{};
	p[0] = 1;
	for (int i = 1; i <= EXACT_POW10; i++) p[i] = p[i - 1] * 10;
	return p;
}
constexpr auto POW10 = powersOfTen();

/** A decimal [+-]digits[.digits][(e|E)[+-]digits] as mantissa * 10^exp10; `exact` is false
 *  when nonzero digits past the 19th significant one were dropped. */
struct Decimal
{
	uint64_t mantissa = 0;
	int exp10 = 0;
	bool negative = false;
	bool exact = true;
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool scanDecimal(std::string_view s, Decimal& d)
{
	size_t i = 0;
	if (i < s.size() && (s[i] == '+' || s[i] == '-')) d.negative = s[i++] == '-';
	bool digits = false, dot = false;
	int significant = 0;
	for (; i < s.size(); i++)
	{
		const char c = s[i];
		if (c == '.' && !dot)
		{
			dot = true;
			continue;
		}
		if (!isDigit(c)) break;
		digits = true;
		if (significant == 0 && c == '0')
			d.exp10 -= dot;	 // a leading zero
		else if (significant < MAX_DIGITS)
		{
			d.mantissa = d.mantissa * 10 + uint64_t(c - '0');
			significant++;
			d.exp10 -= dot;
		}
		else
		{
			d.exact = d.exact && c == '0';
			d.exp10 += !dot;
		}
	}
	if (!digits) return false;
	if (i < s.size() && (s[i] == 'e' || s[i] == 'E'))
	{
		bool negative = false, expDigits = false;
		int e = 0;
		if (++i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
		for (; i < s.size() && isDigit(s[i]); i++, expDigits = true)
			e = std::min(e * 10 + (s[i] - '0'), 100000);
		if (!expDigits) return false;
		d.exp10 += negative ? -e : e;
	}
	return i == s.size();
}

/** from_chars with a leading '+' allowed; the reason on failure. */
template <typename T>
const char* fromChars(std::string_view s, T& out)
{
	if (s.empty()) return "is empty";
	if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
	const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
	if (r.ec == std::errc::result_out_of_range) return "is out of range";
	if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return "is not a number";
	if (!std::isfinite(out)) return "is not finite";
	return nullptr;
}

bool sameBits(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

template <typename T>
void appendShortest(std::string& out, T v)
{
	char buf[64];
	const auto r = std::to_chars(buf, buf + sizeof(buf), v);
	out.append(buf, r.ptr);
}
}  // namespace

const char* ContactLogFormat::parseNumber(std::string_view s, double& out)
{
	return fromChars(s, out);
}

const char* ContactLogFormat::parseDegrees(std::string_view s, double& radians)
{
	long double deg = 0;
	Decimal d;
	if (scanDecimal(s, d) && d.exact && std::abs(d.exp10) <= EXACT_POW10)
	{
		// Both operands exact, so one correctly rounded operation: the same value as strtold.
		const long double m = static_cast<long double>(d.mantissa);
		deg = d.exp10 >= 0 ? m * POW10[d.exp10] : m / POW10[-d.exp10];
		if (d.negative) deg = -deg;
	}
	else if (const char* why = fromChars(s, deg))
		return why;
	radians = static_cast<double>(deg * RAD_PER_DEG);
	return std::isfinite(radians) ? nullptr : "is out of range";
}

const char* ContactLogFormat::parseTime(std::string_view s, mrpt::Clock::time_point& out)
{
	Decimal d;
	if (s.empty()) return "is empty";
	if (!scanDecimal(s, d)) return "is not a number";
	if (!d.exact) return "has more than 19 significant digits";
	const int p = d.exp10 + 7;	// ticks = mantissa * 10^p
	constexpr uint64_t LIMIT = std::numeric_limits<int64_t>::max() - UNIX_EPOCH_TICKS;
	constexpr const char* OUT_OF_RANGE = "is out of range (before 1601 or after 30000)";
	uint64_t ticks = d.mantissa;
	if (p > 0)
	{
		for (int k = 0; k < p && ticks != 0; k++)
		{
			if (ticks > LIMIT / 10) return OUT_OF_RANGE;
			ticks *= 10;
		}
	}
	else if (p < 0)
	{
		if (p < -MAX_DIGITS)
			ticks = 0;	// below half a tick
		else
		{
			uint64_t div = 1;
			for (int k = 0; k < -p; k++) div *= 10;
			ticks = d.mantissa / div + (d.mantissa % div >= div - div / 2);	 // to nearest
		}
	}
	if (ticks > LIMIT || (d.negative && ticks > uint64_t(UNIX_EPOCH_TICKS)))
		return OUT_OF_RANGE;
	const int64_t unixTicks = d.negative ? -int64_t(ticks) : int64_t(ticks);
	out = mrpt::Clock::time_point(mrpt::Clock::duration(unixTicks + UNIX_EPOCH_TICKS));
	return nullptr;
}

void ContactLogFormat::appendNumber(std::string& out, double v) { appendShortest(out, v); }

void ContactLogFormat::appendDegrees(std::string& out, double radians)
{
	const long double deg = radians * DEG_PER_RAD;
	auto readsBack = [&](const std::string& text)
	{
		double back = 0;
		return parseDegrees(text, back) == nullptr && sameBits(back, radians);
	};
	std::string text;
	appendShortest(text, static_cast<double>(deg));	 // short, and enough for most values
	if (!readsBack(text))
	{
		text.clear();
		appendShortest(text, deg);	// reads back as `deg` itself: always exact
		if (!readsBack(text))
			throw core::Error(
				"contact log: angle " + text + " deg has no exact text form on this platform");
	}
	out += text;
}

void ContactLogFormat::appendTime(std::string& out, mrpt::Clock::time_point t)
{
	const int64_t unixTicks = t.time_since_epoch().count() - UNIX_EPOCH_TICKS;
	const uint64_t a = unixTicks < 0 ? uint64_t(-unixTicks) : uint64_t(unixTicks);
	if (unixTicks < 0) out += '-';
	out += std::to_string(a / TICKS_PER_SECOND);
	uint64_t frac = a % TICKS_PER_SECOND;
	if (frac == 0) return;
	char digits[8] = "0000000";
	for (int i = 6; i >= 0; i--, frac /= 10) digits[i] = char('0' + frac % 10);
	int n = 7;
	while (digits[n - 1] == '0') n--;
	out += '.';
	out.append(digits, size_t(n));
}
}  // namespace whiskermap::world
