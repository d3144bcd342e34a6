// CAD files through Open CASCADE: a STEP file, or an IGES file when the input does not start with
// STEP's "ISO-10303-21" (the reader is chosen by the file's extension).

#include "fuzz_target.hpp"
#include "scratch_folder.hpp"
#include "tandem/core/error.hpp"
#include "tandem/scene/cad_loader.hpp"

namespace tandem::fuzz {

bool step(std::string_view input) {
  fresh_scratch_folder();
  const bool is_step = input.substr(0, 12) == "ISO-10303-21";
  const std::filesystem::path file = write_scratch_file(is_step ? "part.step" : "part.igs", input);
  try {
    (void)load_cad(file);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace tandem::fuzz
