#pragma once
// C++ structs as numpy structured arrays, field by field (names and units of the structs).
// Out: one record per element, the struct's fields packed (no padding: no stray bytes).
// In: any structured array that has the fields by name (packed or not, extra fields
// ignored; optional ones may be missing), each field converted to the struct member's type.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/TMappedObject.h>
#include <whiskermap/obs/Shapelet.h>
#include <whiskermap/obs/TWhisker.h>
#include <whiskermap/world/Table.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace whiskermap::python
{
namespace py = pybind11;

/** One member of a struct: numpy field name, numpy format ("f8", "?", "i4", "u4", "u8"),
 *  byte offset and size in the struct; an optional one may be missing from an input array
 *  (the member keeps its default). */
struct Field
{
	const char* name;
	const char* format;
	size_t offset, size;
	bool optional = false;
};

/** The fields of a struct, in order: specialised in Records.cpp for these. */
template <class T>
const std::vector<Field>& fieldsOf();
template <>
const std::vector<Field>& fieldsOf<obs::TWhisker>();
template <>
const std::vector<Field>& fieldsOf<obs::Shapelet>();
template <>
const std::vector<Field>& fieldsOf<world::Table>();
template <>
const std::vector<Field>& fieldsOf<maps::TMappedObject>();
template <>
const std::vector<Field>& fieldsOf<world::WhiskerSimulator::Truth>();

/** The struct's fields, packed (no padding), in the struct's order. */
template <class T>
py::dtype dtypeOf()
{
	static_assert(std::is_trivially_copyable_v<T> && std::is_standard_layout_v<T>);
	py::list fields;
	for (const auto& f : fieldsOf<T>()) fields.append(py::make_tuple(f.name, f.format));
	return py::dtype::from_args(fields);
}

/** The elements as a 1-D structured array (a copy). */
template <class T>
py::array toArray(const std::vector<T>& v)
{
	py::array a(dtypeOf<T>(), static_cast<py::ssize_t>(v.size()));
	auto* out = static_cast<char*>(a.mutable_data());
	for (const auto& e : v)
		for (const auto& f : fieldsOf<T>())
		{
			std::memcpy(out, reinterpret_cast<const char*>(&e) + f.offset, f.size);
			out += f.size;
		}
	return a;
}

/** A 1-D structured array (or anything numpy makes one of) with T's fields, by name.
 *  `what` names the argument in errors. */
template <class T>
std::vector<T> fromArray(const py::handle& obj, const std::string& what)
{
	const auto np = py::module_::import("numpy");
	const py::array a = np.attr("asarray")(obj);
	const py::object fieldNames = a.dtype().attr("names");
	if (a.ndim() != 1 || fieldNames.is_none())
		throw core::Error(what + ": expected a 1-D numpy structured array (fields by name)");
	const auto names = fieldNames.cast<std::vector<std::string>>();
	std::vector<T> out(static_cast<size_t>(a.shape(0)));
	for (const auto& f : fieldsOf<T>())
	{
		if (std::find(names.begin(), names.end(), f.name) == names.end())
		{
			if (f.optional) continue;
			throw core::Error(what + ": no field '" + f.name + "'");
		}
		const py::array col = np.attr("ascontiguousarray")(a[py::str(f.name)], py::str(f.format));
		const auto* src = static_cast<const char*>(col.data());
		if (static_cast<size_t>(col.itemsize()) != f.size) throw std::logic_error(std::string("field size of ") + f.name);
		for (size_t i = 0; i < out.size(); i++)
			std::memcpy(reinterpret_cast<char*>(&out[i]) + f.offset, src + i * f.size, f.size);
	}
	return out;
}
}  // namespace whiskermap::python
