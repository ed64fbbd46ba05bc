#pragma once
#include <whiskermap/model/Id.h>
#include <whiskermap/model/Leg.h>
#include <whiskermap/model/Table.h>

#include <vector>

namespace whiskermap::model
{
/** A compact copy of a blackboard's live hypotheses and links (for results and drawing):
 *  Leg::parent indexes `tables`, shapeletParent[i] indexes `legs` (NONE: no parent). */
struct HypothesisSet
{
	std::vector<Table> tables;
	std::vector<Leg> legs;
	std::vector<Id> shapeletParent;  ///< one per shapelet, in the blackboard's order
};
}  // namespace whiskermap::model
