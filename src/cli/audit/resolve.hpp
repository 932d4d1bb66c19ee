// Mesh references of a robot description turned into file paths, as the
// simulators find them:
// - package://NAME/PATH: the package's directory NAME/ or one whose
//   package.xml says <name>NAME</name>, found under each root of
//   ROS_PACKAGE_PATH (colon-separated; the root itself, or a directory up to
//   two levels below it), else in the description's own directory or one
//   above it (a package.xml naming NAME there, or a directory called NAME
//   there or beside it);
// - model://NAME/PATH: NAME/ under each root of GZ_SIM_RESOURCE_PATH,
//   IGN_GAZEBO_RESOURCE_PATH, SDF_PATH, GAZEBO_MODEL_PATH, else the
//   description's directory or one above it called NAME, or with NAME/ in it;
// - file:///ABSOLUTE, file://RELATIVE, an absolute path;
// - anything else: relative to the description's directory.
#pragma once

#include <string>

namespace polymass_cli::audit {

struct Resolved {
    std::string path;   // the file, when found
    std::string error;  // why not, when not
};

Resolved resolve_mesh(const std::string& uri, const std::string& description_path);

}  // namespace polymass_cli::audit
