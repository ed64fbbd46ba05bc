// Registers the map class with MRPT's class registry when the library is loaded, so maps
// saved inside CMultiMetricMap / CSimpleMap files deserialize by name.
#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>

MRPT_INITIALIZER(whiskermap_maps_register_classes)
{
	mrpt::rtti::registerClass(CLASS_ID(whiskermap::maps::CHierarchicalObjectMap));
}
