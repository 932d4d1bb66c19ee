// libFuzzer target: arbitrary bytes as a robot description (URDF, SDFormat or
// MJCF: the root element says which) through polymass audit: parsed, its mesh
// references resolved, the meshes read and measured, the links judged, the
// JSON report and the --fix text written (to nowhere).
//
// The description is written at each execution into a sandbox directory of
// this process, which holds the meshes a reference may name (meshes/cube.stl,
// meshes/cube.obj, and a package "robot" with its package.xml, for
// package://robot/meshes/...); the search paths of package:// and model://
// point there only; a relative reference resolves from the description's
// directory. References outside it (an absolute path) are followed as the
// tool follows them: the dictionary names no such path. The working directory
// is left alone: libFuzzer's -fork mode names its files relative to it.
//
// audit_file never throws for a bad description (it says so in its error)
// and the report and fix take any audit it returns: any exception escaping,
// or a crash, is a finding.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "arguments.hpp"
#include "audit/audit.hpp"
#include "audit/fix.hpp"
#include "audit/report.hpp"
#include "commands/commands.hpp"

namespace {

void write_file(const std::string& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!file) std::abort();
}

const char kCubeStl[] =
    "solid cube\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 1\nvertex 1 0 1\nvertex 1 1 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 1\nvertex 1 1 1\nvertex 0 1 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 0 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 1\nvertex 0 0 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 1 0\nvertex 0 1 1\nvertex 1 1 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 1 0\nvertex 1 1 1\nvertex 1 1 0\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 1\nvertex 0 1 0\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 1 1 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 1 1 1\nvertex 1 0 1\nendloop\nendfacet\n"
    "endsolid cube\n";

const char kCubeObj[] =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

// The sandbox, made once: its path, with the description's file name.
const std::string& description_path() {
    static const std::string path = [] {
        char directory[] = "/tmp/polymass-fuzz-audit-XXXXXX";
        if (!mkdtemp(directory)) std::abort();
        const std::string root = directory;
        for (const char* sub : {"/meshes", "/robot", "/robot/meshes"}) {
            if (mkdir((root + sub).c_str(), 0700) != 0) std::abort();
        }
        write_file(root + "/meshes/cube.stl", kCubeStl);
        write_file(root + "/meshes/cube.obj", kCubeObj);
        write_file(root + "/robot/package.xml", "<package><name>robot</name></package>\n");
        write_file(root + "/robot/meshes/cube.stl", kCubeStl);
        for (const char* variable : {"ROS_PACKAGE_PATH", "GZ_SIM_RESOURCE_PATH",
                                     "IGN_GAZEBO_RESOURCE_PATH", "SDF_PATH", "GAZEBO_MODEL_PATH"}) {
            setenv(variable, root.c_str(), 1);
        }
        return root + "/robot.urdf";
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace polymass_cli;
    const std::string& path = description_path();
    write_file(path, std::string(reinterpret_cast<const char*>(data), size));

    audit::AuditSettings settings;
    settings.options = options_for(Arguments{});
    const Library library(settings.options);
    const audit::FileAudit file = audit::audit_file(library, path, settings);
    std::ostringstream report;
    audit::write_audit_json(report, {file});
    audit::write_audit_table(report, {file});
    if (file.error.empty()) audit::fix_description(file, audit::FixSettings{});
    return 0;
}
