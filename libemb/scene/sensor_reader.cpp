#include "libemb/scene/sensor_reader.h"

#include <memory>
#include <set>

#include "libemb/common/error.h"
#include "libemb/mbs/core/chord_sensor.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {

void ReadSensors(const YAML::Node& list, const std::string& file, mbs::System* sys) {
  std::set<std::string> names;
  ReadNamedList(
      list, file, "sensors", "sensor", [&](MapReader& r, const std::string& name, const YAML::Node&) {
        EMB_THROW_IF(!names.insert(name).second, "sensor '" << name << "' is defined twice");
        const std::string type = r.GetString("type", "pose");
        if (type == "pose") {
          const std::string i = r.GetString("i"), j = r.GetString("j");
          r.Finish();
          sys->AddSensor(name, i, j);
          return;
        }
        EMB_THROW_IF(type != "chord", r.what() << " type: expected 'pose' (marker i relative to "
                                                  "marker j) or 'chord' (a point relative to "
                                                  "the line through two markers), got '"
                                               << type << "'");
        const std::string point = r.GetString("point");
        const YAML::Node chord = r.Require("chord");
        EMB_THROW_IF(!chord.IsSequence() || chord.size() != 2 || !chord[0].IsScalar() ||
                         !chord[1].IsScalar(),
                     Where(file, chord) << ": " << r.what()
                                        << " chord: expected the two markers at its ends, "
                                           "[marker_a, marker_b]");
        r.Finish();
        sys->AddProbe(std::make_shared<mbs::ChordSensor>(
            *sys, name, sys->FindMarker(point), sys->FindMarker(chord[0].Scalar()),
            sys->FindMarker(chord[1].Scalar())));
      });
}


}  // namespace emb::scene
