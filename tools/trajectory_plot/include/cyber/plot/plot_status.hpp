#pragma once
// Why a picture was not written: the status of every cyber::Result of the plot library, whose
// message starts with the path of the picture.

namespace cyber::plot {

enum class PlotStatus {
  kOk,
  kNothingToDraw,  // a move without samples, an animation without frames
  kCannotEncode,   // cairo could not encode a frame, or the frames differ in size or format
  kCannotWrite,    // the file cannot be written
};

}  // namespace cyber::plot
