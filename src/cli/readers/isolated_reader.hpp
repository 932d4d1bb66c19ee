// Running a reader in a child process, so that a crash inside it is a
// ReadError, not the end of the tool.
//
// The readers built on other libraries (tinygltf, lib3mf; assimp, which the
// tool used before, aborted on a 3MF with a bad zip checksum) parse untrusted
// JSON, buffers and zip packages with code the project cannot fix. They run in
// a forked child that sends the Model back through a pipe; the parent turns a
// child killed by a signal into a ReadError saying so.
#pragma once

#include <functional>

#include "model/model.hpp"

namespace polymass_cli {

// Calls read() in a child process and returns its Model, or throws the
// ReadError it threw, or a ReadError when it crashed.
Model read_isolated(const std::function<Model()>& read);

}  // namespace polymass_cli
