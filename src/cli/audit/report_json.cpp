#include <map>

#include "audit/report.hpp"
#include "reports/json_output.hpp"

namespace polymass_cli::audit {
namespace {

Json vector_json(const Eigen::Vector3d& v) { return json_numbers(v.data(), 3); }

Json tensor_json(const Eigen::Matrix3d& m) {
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rows = m;
    return json_tensor(rows.data());
}

Json declared_json(const Inertial& declared) {
    return Json{{"mass", json_number(declared.mass)},
                {"center_of_mass", vector_json(declared.center_of_mass)},
                {"inertia", tensor_json(declared.inertia)}};
}

Json computed_json(const Computed& computed) {
    return Json{{"volume", json_number(computed.volume)},
                {"mass", json_number(computed.mass)},
                {"density", json_number(computed.density)},
                {"center_of_mass", vector_json(computed.center_of_mass)},
                {"inertia", tensor_json(computed.inertia)},
                {"principal_moments", vector_json(computed.principal_moments)},
                {"rules", computed.rules}};
}

Json file_json(const FileAudit& file) {
    Json object = Json::object();
    object["file"] = file.path;
    if (!file.error.empty()) {
        object["error"] = file.error;
        return object;
    }
    object["format"] = format_name(file.format);
    Json links = Json::array();
    for (const LinkAudit& link : file.links) {
        Json entry = Json::object();
        entry["name"] = link.name;
        entry["geometry"] = link.geometry;
        entry["declared"] = link.declared ? declared_json(*link.declared) : Json();
        entry["computed"] = link.computed ? computed_json(*link.computed) : Json();
        if (link.mujoco_uses != nullptr) entry["mujoco_uses"] = link.mujoco_uses;
        if (link.mujoco_legacy) entry["mujoco_legacy"] = computed_json(*link.mujoco_legacy);
        Json findings = Json::array();
        for (const Finding& finding : link.findings) {
            findings.push_back({{"kind", finding.kind},
                                {"severity", severity_name(finding.severity)},
                                {"message", finding.message}});
        }
        entry["findings"] = findings;
        links.push_back(entry);
    }
    object["links"] = links;
    return object;
}

}  // namespace

void write_audit_json(std::ostream& out, const std::vector<FileAudit>& files) {
    print_json(out, audit_json_document(files));
}

Json audit_json_document(const std::vector<FileAudit>& files) {
    if (files.size() == 1) return file_json(files.front());
    Json all = Json::array();
    std::map<std::string, int> kinds;
    std::size_t links = 0, unreadable = 0;
    for (const FileAudit& file : files) {
        all.push_back(file_json(file));
        unreadable += file.error.empty() ? 0 : 1;
        links += file.links.size();
        for (const LinkAudit& link : file.links) {
            for (const Finding& finding : link.findings) ++kinds[finding.kind];
        }
    }
    Json document = Json::object();
    document["files"] = all;
    document["summary"] = {
        {"files", files.size()}, {"unreadable", unreadable}, {"links", links}, {"findings", kinds}};
    return document;
}

}  // namespace polymass_cli::audit
