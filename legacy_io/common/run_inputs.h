// No output of a run may overwrite one of its inputs (`trace --out
// DIR/prim/PrimFile`, `export G G`, `--png DIR/Model.txt`).
//
// While a RunInputs scope exists (the CLI opens one around every command),
// every file read through readInputFile is recorded by device and inode, and
// a command may add files it protects without reading them (a PRIME scene's
// text inputs and databases). checkOutputPath, and so every OutputFile,
// refuses a target that resolves to a recorded file: the same inode, reached
// by the same name, another name, a hard link or a symbolic link. A target
// that does not exist yet cannot be an input. Outside a scope (unit tests
// that write, read and rewrite the same file) nothing is recorded.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prime::io {

class RunInputs {
 public:
  RunInputs();
  ~RunInputs();
  RunInputs(const RunInputs&) = delete;
  RunInputs& operator=(const RunInputs&) = delete;
};

// Records the file at `path` (shown as `display` in messages) as an input of
// the current run, if a RunInputs scope is open and the file exists.
void protectInput(const std::string& path, const std::string& display = "");
// The same for an already open file (readInputFile calls it with its fstat).
void noteInput(unsigned long long device, unsigned long long inode, const std::string& display);
// The same, with the bytes read (readInputFile calls it): their hash goes
// into inputsDigest().
void noteInputContent(unsigned long long device, unsigned long long inode,
                      const std::string& display, const void* bytes, std::size_t size);
// One hash of every input read whole so far in the current run (the hashes
// of their bytes, sorted: neither the order of reading nor the names the
// files were read by count), leaving out the files `excluding` names; 0
// outside a scope. For the render records of films and bands (a frame or a
// piece is of the same render when its scene's files hold the same bytes).
std::uint64_t inputsDigest(const std::vector<std::string>& excluding = {});
// Forgets the bytes read so far for inputsDigest (not the inputs: they stay
// protected). PRIME's --model calls it after building the databases: a
// render's digest is of what it read (the databases), the same whether this
// run or an earlier one built them.
void forgetInputsContent();
// Throws InputError naming both files if `output` resolves to an input of the
// current run.
void refuseIfInput(const std::string& output);

}  // namespace prime::io
