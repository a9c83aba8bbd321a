// Prints each public move (tests/support/public_moves.hpp) as one line: its label, then the
// cyber-plan arguments that plan it. public_moves.sh plans them with both builds' cyber-plan.
#include <cstdio>

#include <string>

#include "public_moves.hpp"
#include "reference_model.hpp"

int main() {
  for (const cyber::test::PublicMove& move : cyber::test::publicMoves()) {
    const std::string pieces = cyber::test::referenceModel().pieceSetName(move.pieces);
    std::printf("%s --from %.17g,%.17g --to %.17g,%.17g%s%s\n", move.label.c_str(), move.from[0], move.from[1],
                move.to[0], move.to[1], move.pieces.empty() ? "" : " --pieces ",
                move.pieces.empty() ? "" : pieces.c_str());
  }
  return 0;
}
