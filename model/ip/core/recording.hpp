// SPDX-License-Identifier: MIT
// Recording file I/O (docs/contracts.md, recording file): `#` comment/metadata lines, one header
// row, then numbers.
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

namespace acore {

// One sensor recording. Four-channel recordings fill ch[0..3] = c1..c4; two-channel recordings
// fill ch[0] = sin and ch[1] = cos (already differential) and leave ch[2], ch[3] empty.
struct Recording {
  int channels = 4;                         // 4 (c1..c4) or 2 (sin, cos)
  std::array<std::vector<double>, 4> ch;    // channel samples, see above
  std::vector<double> theta_ref;            // reference angle, rad (empty when absent)
  std::vector<double> t;                    // seconds (empty when absent)
  std::vector<double> temp;                 // degrees Celsius (empty when absent)
  std::map<std::string, std::string> meta;  // `# key=value` lines
  std::vector<std::string> comments;        // other `#` lines, without the `#`

  size_t size() const { return ch[0].size(); }
  bool has_theta() const { return !theta_ref.empty(); }
  bool has_t() const { return !t.empty(); }
  bool has_temp() const { return !temp.empty(); }
  // The pre-filter's differential pair: c1 - c3 and c2 - c4, or sin and cos for two channels.
  double d13(size_t i) const { return channels == 4 ? ch[0][i] - ch[2][i] : ch[0][i]; }
  double d24(size_t i) const { return channels == 4 ? ch[1][i] - ch[3][i] : ch[1][i]; }
  // Throws InputError naming `what` when the columns have different lengths.
  void check_consistent(const std::string& what) const;
};

// How many of the 36 ten-degree sectors of one turn of p * theta (wrapped) hold a sample: 36 means
// the angles cover a full (electrical) turn. Used wherever a fit needs the whole circle.
int turn_sectors_covered(const std::vector<double>& theta, int periodicity = 1);

// `# p=N` in the recording's metadata, else 1; throws InputError naming `what` (the file) on a
// malformed value.
int recording_periodicity(const Recording& rec, const std::string& what);

// Reads a recording; throws InputError "FILE:LINE: column 'NAME': ..." on any defect.
Recording read_recording(const std::string& path);
// Parses recording text; `name` is used in error messages in place of a path.
Recording parse_recording(const std::string& text, const std::string& name);
// Writes a recording (metadata and comments first, then the header, %.17g numbers).
void write_recording(const Recording& rec, const std::string& path);
std::string format_recording(const Recording& rec);

}  // namespace acore
