// Registers whiskermap's observation classes with MRPT's class registry when the library
// is loaded (IMPLEMENTS_SERIALIZABLE alone does not), so rawlogs holding them can be read
// by our apps and by stock MRPT tools given this library as a plugin.
#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

MRPT_INITIALIZER(whiskermap_obs_register_classes)
{
	mrpt::rtti::registerClass(CLASS_ID(whiskermap::obs::CObservationWhiskerContacts));
}
