#include "Records.h"

#include <cstddef>

namespace whiskermap::python
{
#define WM_FIELD(T, member, format) Field{#member, format, offsetof(T, member), sizeof(T::member)}

template <>
const std::vector<Field>& fieldsOf<obs::TWhisker>()
{
	using W = obs::TWhisker;
	static const std::vector<Field> f{
		WM_FIELD(W, mount_x, "f8"), WM_FIELD(W, mount_y, "f8"), WM_FIELD(W, sweep_start, "f8"),
		WM_FIELD(W, sweep_end, "f8"), WM_FIELD(W, length, "f8"),   WM_FIELD(W, touched, "?"),
		WM_FIELD(W, angle, "f8"),     WM_FIELD(W, r, "f8"),        WM_FIELD(W, normal, "f8"),
		WM_FIELD(W, texture, "f8")};
	return f;
}

template <>
const std::vector<Field>& fieldsOf<obs::Shapelet>()
{
	using S = obs::Shapelet;
	static const std::vector<Field> f{
		WM_FIELD(S, x, "f8"), WM_FIELD(S, y, "f8"), WM_FIELD(S, normal, "f8"), WM_FIELD(S, texture, "f8"),
		WM_FIELD(S, whisker, "i4"), WM_FIELD(S, shaft_x, "f8"), WM_FIELD(S, shaft_y, "f8")};
	return f;
}

template <>
const std::vector<Field>& fieldsOf<world::Table>()
{
	using T = world::Table;
	static const std::vector<Field> f{
		WM_FIELD(T, x, "f8"),     WM_FIELD(T, y, "f8"),         WM_FIELD(T, yaw, "f8"),
		WM_FIELD(T, length, "f8"), WM_FIELD(T, width, "f8"),    WM_FIELD(T, leg_width, "f8"),
		WM_FIELD(T, texture, "f8")};
	return f;
}

template <>
const std::vector<Field>& fieldsOf<maps::TMappedObject>()
{
	using O = maps::TMappedObject;
	static const std::vector<Field> f = [] {
		// The table's fields first (flattened), then the object's own.
		std::vector<Field> all;
		for (auto t : fieldsOf<world::Table>()) all.push_back({t.name, t.format, offsetof(O, table) + t.offset, t.size});
		for (auto o : {WM_FIELD(O, existence, "f8"), WM_FIELD(O, contacts, "u8"), WM_FIELD(O, legs, "u4")})
			all.push_back(o);
		for (auto o : {WM_FIELD(O, sd_x, "f8"), WM_FIELD(O, sd_y, "f8"), WM_FIELD(O, sd_yaw, "f8")})
		{
			o.optional = true;  // the pose spread: NaN when an input array lacks it
			all.push_back(o);
		}
		return all;
	}();
	return f;
}
template <>
const std::vector<Field>& fieldsOf<world::WhiskerSimulator::Truth>()
{
	using T = world::WhiskerSimulator::Truth;
	static const std::vector<Field> f{WM_FIELD(T, table, "i4"), WM_FIELD(T, leg, "i4"), WM_FIELD(T, wall, "?")};
	return f;
}
#undef WM_FIELD
}  // namespace whiskermap::python
