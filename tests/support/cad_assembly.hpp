#pragma once
// CAD assemblies for tests, built with Open CASCADE and written to STEP or IGES files by the test
// itself: no binary fixture in the repository.
//
// The housing assembly, in millimetres (z up):
//   housing            (assembly)
//     base             a 100 x 80 x 40 block centred on x = y = 0, z in [0, 40], with a 20 x 20 x
//                      30 pocket cut into its top at the centre; blue on the solid
//     lid-1            (a sub-assembly, placed 80 mm up: 40 mm above the block)
//       lid            a 100 x 80 x 10 plate, z in [0, 10]; its top face red, the rest uncoloured
//     peg              a cylinder, radius 9, height 30, seated in the pocket (its base on the
//                      pocket's floor at z = 10, its axis on x = y = 0); green on the solid
//     peg-spare        the same product placed at (200, 0, 0), turned 90 degrees about x
// The peg rests on the pocket's floor, 1 mm clear of its walls: it comes out straight up, then
// sideways between the block and the lid.

#include <filesystem>
#include <string>

namespace tandem::test {

enum class CadFormat { step, iges };

/// Writes the housing assembly. `unit` is the file's length unit ("MM" or "M"; STEP only).
void write_housing(const std::filesystem::path& file, CadFormat format = CadFormat::step,
                   const std::string& unit = "MM");

/// Writes a STEP file with a header and an empty DATA section: a STEP file with no geometry.
void write_empty_step(const std::filesystem::path& file);

}  // namespace tandem::test
