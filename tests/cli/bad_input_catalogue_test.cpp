// A catalogue of malformed inputs (G-code, Biip dumps, machine descriptions, command options)
// run through isurface-cli. Each row must end with the expected exit code, an error on stderr
// that names the file and the problem, and no output file (nor a temporary one) left behind.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <system_error>
#include <string>
#include <utility>
#include <vector>

#include "test_support.h"

namespace fs = std::filesystem;
using isurface::test::runCli;
using isurface::test::scratchDir;

namespace {

fs::path inDir() { return scratchDir() / "bad-in"; }
fs::path outDir() { return scratchDir() / "bad-out"; }

void writeBytes(const std::string& name, const std::string& bytes) {
  std::ofstream f(inDir() / name, std::ios::binary);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// --- Biip files, built field by field (docs: /work/shared/BIIP.md) ---------------------------

struct Channel {
  std::string name;
  std::uint8_t type = 1;  // f64
  std::uint32_t offset = 0;
};

struct BiipSpec {
  std::string magic = "BIIP";
  std::uint16_t major = 1;
  std::vector<Channel> channels = {{"x", 1, 0}, {"y", 1, 8}, {"z", 1, 16}};
  std::uint32_t recordBytes = 24;
  double cycle = 0.001;
  std::uint64_t records = 3;
  std::int64_t headerBytes = -1;    // -1: the right value
  std::int64_t channelCount = -1;   // -1: channels.size()
  std::uint32_t metadataBytes = 0;  // declared only; no metadata is written
  std::size_t truncateTo = std::string::npos;
  std::vector<double> times;  // the "t" channel's values, record by record (0 past them)
  std::string metadata;       // written after the channel table, metadataBytes set to its size
};

template <typename T>
void put(std::string& s, std::size_t at, T v) {
  std::memcpy(&s[at], &v, sizeof v);  // the test machines are little-endian, like the format
}

std::string biip(const BiipSpec& b) {
  const std::size_t natural = (64 + 32 * b.channels.size() + b.metadata.size() + 7) / 8 * 8;
  std::string s(natural, '\0');
  std::memcpy(&s[0], b.magic.data(), 4);
  put<std::uint16_t>(s, 4, b.major);
  put<std::uint16_t>(s, 6, 0);
  put<std::uint32_t>(s, 8,
                     static_cast<std::uint32_t>(b.headerBytes < 0 ? natural : b.headerBytes));
  put<std::uint32_t>(s, 12,
                     static_cast<std::uint32_t>(b.channelCount < 0 ? b.channels.size()
                                                                   : b.channelCount));
  put<std::uint32_t>(s, 16, b.recordBytes);
  put<double>(s, 24, b.cycle);
  put<std::uint64_t>(s, 32, b.records);
  put<double>(s, 40, 0.0);
  put<std::uint32_t>(s, 48, b.metadata.empty() ? b.metadataBytes : static_cast<std::uint32_t>(b.metadata.size()));
  if (!b.metadata.empty()) std::memcpy(&s[64 + 32 * b.channels.size()], b.metadata.data(), b.metadata.size());
  for (std::size_t i = 0; i < b.channels.size(); ++i) {
    const std::size_t at = 64 + 32 * i;
    const auto& name = b.channels[i].name;
    std::memcpy(&s[at], name.data(), std::min<std::size_t>(24, name.size()));
    s[at + 24] = static_cast<char>(b.channels[i].type);
    put<std::uint32_t>(s, at + 28, b.channels[i].offset);
  }
  for (std::uint64_t r = 0; r < b.records; ++r) {
    std::string rec(b.recordBytes, '\0');
    for (const auto& c : b.channels)
      if (c.type == 1 && c.offset + 8 <= b.recordBytes)
        put<double>(rec, c.offset,
                    c.name == "x"   ? static_cast<double>(r)
                    : c.name == "t" ? (r < b.times.size() ? b.times[r] : 0.0)
                                    : 0.0);
    s += rec;
  }
  if (b.truncateTo != std::string::npos) s.resize(b.truncateTo);
  return s;
}

// --- Machine descriptions ---------------------------------------------------------------------

std::string axisJson(const std::string& acc = "2000", const std::string& gain = "40",
                     const std::string& vff = "0.95") {
  return R"({ "max_velocity_mm_min": 24000, "max_acceleration_mm_s2": )" + acc +
         R"(, "max_jerk_mm_s3": 100000, "position_gain_1_s": )" + gain +
         R"(, "velocity_feed_forward": )" + vff + R"(, "velocity_loop_time_constant_s": 0.002 })";
}

std::string machineJson(const std::string& cycle = "0.001", const std::string& x = axisJson(),
                        const std::string& y = axisJson(), const std::string& z = axisJson(),
                        const std::string& extraAxis = "") {
  return R"({ "name": "catalogue", "cycle_s": )" + cycle +
         R"(, "rapid_mm_min": 24000, "chord_tolerance_mm": 0.01, "axes": { "x": )" + x +
         R"(, "y": )" + y + R"(, "z": )" + z + extraAxis + " } }\n";
}

// --- The inputs -------------------------------------------------------------------------------

void writeInputs() {
  fs::create_directories(inDir());
  fs::create_directories(outDir());

  // G-code
  writeBytes("good.nc", "G0 X0 Y0 Z0\nG1 X10 F1000\nG1 Y10\n");
  writeBytes("num_dots.nc", "G0 X0 Y0 Z0\nG1 X1..2 F100\n");
  writeBytes("num_exp.nc", "G0 X0 Y0 Z0\nG1 X1e999 F100\n");
  writeBytes("num_nan.nc", "G0 X0 Y0 Z0\nG1 Xnan F100\n");
  writeBytes("num_inf.nc", "G0 X0 Y0 Z0\nG1 Xinf F100\n");
  writeBytes("num_long.nc", "G0 X0 Y0 Z0\nG1 X" + std::string(400, '1') + " F100\n");
  writeBytes("nan_expr.nc", "G0 X0 Y0 Z0\nG1 X[0/0] F100\n");
  writeBytes("unknown_g.nc", "G0 X0 Y0 Z0\nG77 X1\n");
  writeBytes("two_x.nc", "G0 X0 Y0 Z0\nG1 X1 X2 F100\n");
  writeBytes("two_motion.nc", "G0 X0 Y0 Z0\nG0 G1 X1 F100\n");
  writeBytes("arc_mismatch.nc", "G0 X0 Y0 Z0\nG17 G2 X10 Y0 I3 J0 F100\n");
  writeBytes("arc_r_small.nc", "G0 X0 Y0 Z0\nG17 G2 X10 Y0 R2 F100\n");
  writeBytes("zero_feed.nc", "G0 X0 Y0 Z0\nG1 X10 F0\n");
  writeBytes("open_comment.nc", "G0 X0 Y0 Z0\n(never closed\n");
  writeBytes("endless_dwell.nc", "G0 X0 Y0 Z0\nG4 P999999999\n");
  writeBytes("endless_feed.nc", "G0 X0 Y0 Z0\nG1 X99999 F0.0001\n");
  {
    std::string junk;
    std::uint32_t state = 12345;
    for (int i = 0; i < 4096; ++i) {
      state = state * 1103515245u + 12345u;
      junk += static_cast<char>(0x80 | ((state >> 16) & 0x7f));  // never ASCII
    }
    writeBytes("junk.nc", junk);
  }
  writeBytes("long_line.nc", "G0 X0\nG1 X1 F100" + std::string(2 * 1024 * 1024, ' ') + "G77\n");

  // Biip
  writeBytes("ok.biip", biip({}));
  writeBytes("empty.biip", "");
  { BiipSpec b; b.magic = "BIPP"; writeBytes("magic.biip", biip(b)); }
  { BiipSpec b; b.major = 2; writeBytes("major.biip", biip(b)); }
  { BiipSpec b; b.truncateTo = 40; writeBytes("short_header.biip", biip(b)); }
  { BiipSpec b; b.truncateTo = 100; writeBytes("short_table.biip", biip(b)); }
  { BiipSpec b; b.channels[2].offset = 20; writeBytes("chan_outside.biip", biip(b)); }
  { BiipSpec b; b.channels[2].name = "x"; writeBytes("dup_chan.biip", biip(b)); }
  { BiipSpec b; b.cycle = 0; writeBytes("cycle0.biip", biip(b)); }
  { BiipSpec b; b.cycle = -0.001; writeBytes("cycle_neg.biip", biip(b)); }
  { BiipSpec b; b.cycle = std::nan(""); writeBytes("cycle_nan.biip", biip(b)); }
  { BiipSpec b; b.cycle = HUGE_VAL; writeBytes("cycle_inf.biip", biip(b)); }
  { BiipSpec b; b.cycle = 5e-324; writeBytes("cycle_tiny.biip", biip(b)); }
  { BiipSpec b; b.cycle = 1e300; writeBytes("cycle_huge.biip", biip(b)); }
  { BiipSpec b; b.channels[0].name = "w"; writeBytes("no_x.biip", biip(b)); }
  { BiipSpec b; b.recordBytes = 0; writeBytes("record0.biip", biip(b)); }
  { BiipSpec b; b.recordBytes = 5000; b.records = 1; writeBytes("record_huge.biip", biip(b)); }
  { BiipSpec b; b.headerBytes = 100000; writeBytes("header_past_end.biip", biip(b)); }
  { BiipSpec b; b.headerBytes = 64; writeBytes("header_small.biip", biip(b)); }
  { BiipSpec b; b.channelCount = 0; b.channels.clear(); writeBytes("no_channels.biip", biip(b)); }
  { BiipSpec b; b.channelCount = 100000; writeBytes("many_channels.biip", biip(b)); }
  { BiipSpec b; b.channels[0].type = 9; writeBytes("bad_type.biip", biip(b)); }
  { BiipSpec b; b.channels[0].name = "X!"; writeBytes("bad_name.biip", biip(b)); }
  { BiipSpec b; b.metadataBytes = 0xffffffffu; writeBytes("meta_huge.biip", biip(b)); }
  const auto timed = [](std::vector<double> times) {
    BiipSpec b;
    b.channels.push_back({"t", 1, 24});
    b.recordBytes = 32;
    b.records = times.size();
    b.times = std::move(times);
    return biip(b);
  };
  writeBytes("t_nan.biip", timed({0.0, std::nan(""), 0.002}));
  writeBytes("t_backwards.biip", timed({0.0, 0.001, 0.0005, 0.002}));
  writeBytes("t_still.biip", timed({5.0, 5.0, 5.0}));

  // Machine descriptions
  writeBytes("m_malformed.json", "{\"name\": \"x\", \"cycle_s\": 0.001,\n \"axes\": {\n");
  writeBytes("m_empty.json", "");
  writeBytes("m_array.json", "[1, 2]\n");
  writeBytes("m_neg_acc.json", machineJson("0.001", axisJson("-5")));
  writeBytes("m_cycle0.json", machineJson("0"));
  writeBytes("m_cycle_tiny.json", machineJson("1e-12"));
  writeBytes("m_cycle_text.json", machineJson("\"fast\""));
  writeBytes("m_cycle_huge.json", machineJson("1e300"));
  writeBytes("m_gain.json", machineJson("0.001", axisJson(), axisJson("2000", "100000")));
  writeBytes("m_axis_q.json",
             machineJson("0.001", axisJson(), axisJson(), axisJson(), ", \"q\": " + axisJson()));
  writeBytes("m_jerk_tiny.json", "{\"axes\": {\"x\": {\"max_jerk_mm_s3\": 1e-300}}}");
  writeBytes("m_neg_vel.json",
             machineJson("0.001", axisJson(), axisJson(),
                         R"({ "max_velocity_mm_min": -1, "max_acceleration_mm_s2": 1500 })"));
  writeBytes("m_overflow.json", machineJson("0.001", axisJson("1e400")));
  // Machine traces
  writeBytes("trace.csv", "x,y,z,ax\n0,0,0,0\n1,0,0,1\n2,0,0,2\n");
  writeBytes("trace_time_inf.csv", "x,y,z,t\n0,0,0,0\n1,0,0,inf\n");
  writeBytes("trace_time_back.csv", "x,y,z,t\n0,0,0,0\n1,0,0,0.2\n2,0,0,0.1\n");
  writeBytes("trace_time_still.csv", "x,y,z,t\n0,0,0,3\n1,0,0,3\n2,0,0,3\n");
  writeBytes("trace_line_neg.csv", "x,y,z,n\n0,0,0,1\n1,0,0,-1\n");
  writeBytes("trace_line_frac.csv", "x,y,z,n\n0,0,0,1\n1,0,0,3.7\n");
  writeBytes("trace_line_huge.csv", "x,y,z,n\n0,0,0,1\n1,0,0,1e11\n");
  writeBytes("m_cycle_only.json", "{\"cycle_s\": 0.1}\n");
  writeBytes("m_huge.json", "{\"comment\": \"" + std::string(3 << 20, 'x') + "\"}\n");
  writeBytes("m_misspelled.json", "{\"rapid_mm_mn\": 5000}\n");
  writeBytes("m_axis_misspelled.json", "{\"axes\": {\"z\": {\"max_jerk_mm_s\": 5000}}}\n");
  {  // the umich preset keeps every numeric column: 250 more than its own are too many channels
    std::string header = "X1_CommandPosition,Y1_CommandPosition,Z1_CommandPosition,X1_ActualPosition,"
                         "Y1_ActualPosition,Z1_ActualPosition,M1_CURRENT_FEEDRATE";
    std::string row = "0,0,0,0,0,0,0";
    for (int c = 0; c < 250; ++c) header += ",c" + std::to_string(c), row += ",0";
    writeBytes("wide.csv", header + "\n" + row + "\n");
  }
  writeBytes("m_vff2.json",
             machineJson("0.001", axisJson(), axisJson(), axisJson("2000", "40", "2")));
}

// --- The catalogue ----------------------------------------------------------------------------

struct Row {
  std::string name;
  std::string args;    // {in}/{out} are replaced by the input and output folders
  int exitCode = 2;
  std::vector<std::string> mustContain;  // on stderr
  std::string output;  // the output file asked for ("" = none; "/dev/..." = not checked)
  std::string skip;    // a known defect: the row is skipped and names it

  Row(std::string name_, std::string args_, int exitCode_, std::vector<std::string> mustContain_,
      std::string output_, std::string skip_ = "")
      : name(std::move(name_)), args(std::move(args_)), exitCode(exitCode_),
        mustContain(std::move(mustContain_)), output(std::move(output_)), skip(std::move(skip_)) {}
};

const std::vector<Row>& catalogue() {
  static const std::vector<Row> rows = {
      // G-code
      {"gcode_number_two_dots", "canon {in}/num_dots.nc -o {out}/num_dots.txt", 2,
       {"num_dots.nc:2:4", "Bad number format", "1..2"}, "num_dots.txt"},
      {"gcode_number_exponent", "canon {in}/num_exp.nc -o {out}/num_exp.txt", 2,
       {"num_exp.nc:2:", "Unknown word starting with E"}, "num_exp.txt"},
      {"gcode_number_nan", "canon {in}/num_nan.nc -o {out}/num_nan.txt", 2,
       {"num_nan.nc:2:4", "X word without a number"}, "num_nan.txt"},
      {"gcode_number_inf", "canon {in}/num_inf.nc -o {out}/num_inf.txt", 2,
       {"num_inf.nc:2:4", "X word without a number"}, "num_inf.txt"},
      {"gcode_number_too_long", "canon {in}/num_long.nc -o {out}/num_long.txt", 2,
       {"num_long.nc:2:4", "Number out of range"}, "num_long.txt"},
      {"gcode_nan_coordinate_expression", "simulate {in}/nan_expr.nc -o {out}/nan_expr.biip", 2,
       {"nan_expr.nc:2:5", "Attempt to divide by zero"}, "nan_expr.biip"},
      {"gcode_unknown_g", "canon {in}/unknown_g.nc -o {out}/unknown_g.txt", 2,
       {"unknown_g.nc:2:1", "Unknown g code used: G77"}, "unknown_g.txt"},
      {"gcode_two_x_words", "canon {in}/two_x.nc -o {out}/two_x.txt", 2,
       {"two_x.nc:2:7", "Multiple x words on one line"}, "two_x.txt"},
      {"gcode_two_motion_codes", "simulate {in}/two_motion.nc -o {out}/two_motion.biip", 2,
       {"two_motion.nc:2:", "Two g codes used from same modal group"}, "two_motion.biip"},
      {"gcode_arc_radius_mismatch", "canon {in}/arc_mismatch.nc -o {out}/arc_mismatch.txt", 2,
       {"arc_mismatch.nc:2:", "Radius to end of arc differs from radius to start"},
       "arc_mismatch.txt"},
      {"gcode_arc_r_too_small", "simulate {in}/arc_r_small.nc -o {out}/arc_r_small.biip", 2,
       {"arc_r_small.nc:2:", "Arc radius too small to reach end point"}, "arc_r_small.biip"},
      {"gcode_zero_feed", "canon {in}/zero_feed.nc -o {out}/zero_feed.txt", 2,
       {"zero_feed.nc:2:1", "Cannot do G1 with zero feed rate"}, "zero_feed.txt"},
      {"gcode_unclosed_comment", "canon {in}/open_comment.nc -o {out}/open_comment.txt", 2,
       {"open_comment.nc:2:1", "Unclosed comment found"}, "open_comment.txt"},
      {"gcode_binary_junk", "simulate {in}/junk.nc -o {out}/junk.biip", 2,
       {"junk.nc:1:1", "Bad character used"}, "junk.biip"},
      {"gcode_2mb_line", "canon {in}/long_line.nc -o {out}/long_line.txt", 2,
       {"long_line.nc:2:2097163", "Unknown g code used: G77"}, "long_line.txt"},
      {"gcode_endless_dwell", "simulate {in}/endless_dwell.nc -o {out}/endless_dwell.biip", 2,
       {"endless_dwell.nc:2:"}, "endless_dwell.biip"},
      {"gcode_endless_feed", "simulate {in}/endless_feed.nc -o {out}/endless_feed.biip", 2,
       {"endless_feed.nc:2:"}, "endless_feed.biip"},
      {"gcode_keep_going_still_fails", "canon --keep-going {in}/unknown_g.nc", 2,
       {"unknown_g.nc:2:1", "Unknown g code used: G77"}, ""},
      {"gcode_bad_program_render",
       "render {in}/zero_feed.nc -o {out}/zero_feed.png --size 64x48", 2,
       {"zero_feed.nc:2:1", "Cannot do G1 with zero feed rate"}, "zero_feed.png"},
      {"gcode_bad_program_analyze", "analyze {in}/arc_r_small.nc -o {out}/arc_r_small.json", 2,
       {"arc_r_small.nc:2:", "Arc radius too small"}, "arc_r_small.json"},

      // Biip
      {"biip_empty", "info {in}/empty.biip -o {out}/empty.json", 2,
       {"empty.biip", "empty file (0 bytes)"}, "empty.json"},
      {"biip_wrong_magic", "info {in}/magic.biip -o {out}/magic.json", 2,
       {"magic.biip", "wrong magic"}, "magic.json"},
      {"biip_unknown_major", "info {in}/major.biip -o {out}/major.json", 2,
       {"major.biip", "unsupported Biip major version 2"}, "major.json"},
      {"biip_truncated_header", "info {in}/short_header.biip -o {out}/short_header.json", 2,
       {"short_header.biip", "file too short for the Biip header"}, "short_header.json"},
      {"biip_truncated_channel_table", "info {in}/short_table.biip -o {out}/short_table.json", 2,
       {"short_table.biip", "header runs past the end of the file"}, "short_table.json"},
      {"biip_channel_outside_record", "info {in}/chan_outside.biip -o {out}/chan_outside.json", 2,
       {"chan_outside.biip", "channel 'z'", "outside the 24-byte record"}, "chan_outside.json"},
      {"biip_duplicate_channel", "info {in}/dup_chan.biip -o {out}/dup_chan.json", 2,
       {"dup_chan.biip", "two channels are named 'x'"}, "dup_chan.json"},
      {"biip_cycle_zero", "info {in}/cycle0.biip -o {out}/cycle0.json", 2,
       {"cycle0.biip", "is not a sample period (1e-6 to 60 s)"}, "cycle0.json"},
      {"biip_cycle_negative", "info {in}/cycle_neg.biip -o {out}/cycle_neg.json", 2,
       {"cycle_neg.biip", "cycle_s -0.001", "is not a sample period"}, "cycle_neg.json"},
      {"biip_cycle_nan", "export {in}/cycle_nan.biip --vtp {out}/cycle_nan.vtp", 2,
       {"cycle_nan.biip", "cycle_s nan is not a sample period"}, "cycle_nan.vtp"},
      {"biip_cycle_inf", "locate {in}/cycle_inf.biip --sample 0", 2,
       {"cycle_inf.biip", "cycle_s inf is not a sample period"}, ""},
      {"biip_cycle_tiny", "info {in}/cycle_tiny.biip -o {out}/cycle_tiny.json", 2,
       {"cycle_tiny.biip", "cycle_s 4.94066e-324 is not a sample period"}, "cycle_tiny.json"},
      {"biip_cycle_huge", "compare {in}/cycle_huge.biip {in}/cycle_huge.biip -o {out}/cycle_huge.json", 2,
       {"cycle_huge.biip", "cycle_s 1e+300 is not a sample period"}, "cycle_huge.json"},
      {"biip_no_x_channel", "info {in}/no_x.biip -o {out}/no_x.json", 2,
       {"no_x.biip", "no 'x' channel"}, "no_x.json"},
      {"biip_record_bytes_zero", "info {in}/record0.biip -o {out}/record0.json", 2,
       {"record0.biip", "record_bytes 0 is outside 1..4096"}, "record0.json"},
      {"biip_record_bytes_too_large", "info {in}/record_huge.biip -o {out}/record_huge.json", 2,
       {"record_huge.biip", "record_bytes 5000 is outside 1..4096"}, "record_huge.json"},
      {"biip_header_bytes_past_end", "info {in}/header_past_end.biip -o {out}/hpe.json", 2,
       {"header_past_end.biip", "header runs past the end of the file", "100000"}, "hpe.json"},
      {"biip_header_bytes_too_small", "info {in}/header_small.biip -o {out}/header_small.json", 2,
       {"header_small.biip", "header_bytes 64 is smaller than"}, "header_small.json"},
      {"biip_no_channels", "info {in}/no_channels.biip -o {out}/no_channels.json", 2,
       {"no_channels.biip", "channel_count 0 is outside 1..256"}, "no_channels.json"},
      {"biip_too_many_channels", "info {in}/many_channels.biip -o {out}/many.json", 2,
       {"many_channels.biip", "channel_count 100000 is outside 1..256"}, "many.json"},
      {"biip_unknown_channel_type", "info {in}/bad_type.biip -o {out}/bad_type.json", 2,
       {"bad_type.biip", "unknown type 9"}, "bad_type.json"},
      {"biip_bad_channel_name", "info {in}/bad_name.biip -o {out}/bad_name.json", 2,
       {"bad_name.biip", "is not made of [a-z0-9_]"}, "bad_name.json"},
      {"biip_metadata_past_header", "info {in}/meta_huge.biip -o {out}/meta_huge.json", 2,
       {"meta_huge.biip", "4294967295 metadata bytes"}, "meta_huge.json"},
      {"biip_bad_dump_render",
       "render {in}/good.nc {in}/magic.biip -o {out}/magic.png --size 64x48",
       2, {"magic.biip", "does not begin with the bytes 'BIIP'"}, "magic.png"},
      {"biip_bad_dump_analyze", "analyze {in}/good.nc {in}/dup_chan.biip -o {out}/dup_chan_an.json",
       2, {"dup_chan.biip", "two channels are named 'x'"}, "dup_chan_an.json"},

      // Machine descriptions
      {"machine_malformed_json",
       "simulate {in}/good.nc --machine {in}/m_malformed.json -o {out}/m_malformed.biip", 2,
       {"m_malformed.json", "not valid JSON", "line 3"}, "m_malformed.biip"},
      {"machine_empty_file",
       "simulate {in}/good.nc --machine {in}/m_empty.json -o {out}/m_empty.biip",
       2, {"m_empty.json", "not valid JSON"}, "m_empty.biip"},
      {"machine_not_an_object",
       "simulate {in}/good.nc --machine {in}/m_array.json -o {out}/m_array.biip", 2,
       {"m_array.json", "must be a JSON object"}, "m_array.biip"},
      {"machine_negative_acceleration",
       "simulate {in}/good.nc --machine {in}/m_neg_acc.json -o {out}/m_neg_acc.biip", 2,
       {"m_neg_acc.json", "axes.x.max_acceleration_mm_s2 must be greater than 0"},
       "m_neg_acc.biip"},
      {"machine_cycle_zero",
       "simulate {in}/good.nc --machine {in}/m_cycle0.json -o {out}/m_cycle0.biip", 2,
       {"m_cycle0.json", "cycle_s must be greater than 0"}, "m_cycle0.biip"},
      {"machine_cycle_tiny",
       "simulate {in}/good.nc --machine {in}/m_cycle_tiny.json -o {out}/m_cycle_tiny.biip", 2,
       {"m_cycle_tiny.json", "cycle_s must be at least 1e-05 s"}, "m_cycle_tiny.biip"},
      {"machine_cycle_not_a_number",
       "simulate {in}/good.nc --machine {in}/m_cycle_text.json -o {out}/m_cycle_text.biip", 2,
       {"m_cycle_text.json", "cycle_s must be a number"}, "m_cycle_text.biip"},
      {"machine_cycle_too_long", "intervals {in}/good.nc --machine {in}/m_cycle_huge.json", 2,
       {"m_cycle_huge.json", "cycle_s must be at most 0.1 s"}, ""},
      {"machine_gain_too_high",
       "simulate {in}/good.nc --machine {in}/m_gain.json -o {out}/m_gain.biip", 2,
       {"m_gain.json", "axes.y.position_gain_1_s is too high"}, "m_gain.biip"},
      {"machine_unknown_axis",
       "simulate {in}/good.nc --machine {in}/m_axis_q.json -o {out}/m_axis_q.biip", 2,
       {"m_axis_q.json", "axes.q: unknown axis"}, "m_axis_q.biip"},
      {"machine_jerk_too_small",
       "simulate {in}/good.nc --machine {in}/m_jerk_tiny.json -o {out}/m_jerk_tiny.biip", 2,
       {"m_jerk_tiny.json", "axes.x.max_jerk_mm_s3 must be 0 (not limited) or at least"}, "m_jerk_tiny.biip"},
      {"machine_negative_velocity",
       "simulate {in}/good.nc --machine {in}/m_neg_vel.json -o {out}/m_neg_vel.biip", 2,
       {"m_neg_vel.json", "axes.z.max_velocity_mm_min must be greater than 0", "got -1"},
       "m_neg_vel.biip"},
      {"machine_number_overflow",
       "simulate {in}/good.nc --machine {in}/m_overflow.json -o {out}/m_overflow.biip", 2,
       {"m_overflow.json", "1e400"}, "m_overflow.biip"},
      {"machine_feed_forward_2",
       "render {in}/good.nc --machine {in}/m_vff2.json -o {out}/m_vff2.png --size 64x48", 2,
       {"m_vff2.json", "axes.z.velocity_feed_forward must be between 0 and 1"}, "m_vff2.png"},
      {"machine_missing_file",
       "simulate {in}/good.nc --machine {in}/no_such_machine.json -o {out}/m_missing.biip", 2,
       {"no_such_machine.json"}, "m_missing.biip"},

      // Command options
      {"option_size_0x0", "render {in}/good.nc -o {out}/size0.png --size 0x0", 2,
       {"bad --size '0x0'"}, "size0.png"},
      {"option_size_text", "render {in}/good.nc -o {out}/size_text.png --size abc", 2,
       {"bad --size 'abc'"}, "size_text.png"},
      {"option_range_reversed", "render {in}/good.nc -o {out}/range.png --range 5:1", 2,
       {"bad range '5:1'"}, "range.png"},
      {"option_percentiles_reversed", "render {in}/good.nc -o {out}/pct.png --percentiles 99:1", 2,
       {"bad range '99:1'"}, "pct.png"},
      {"option_unknown_color", "render {in}/good.nc -o {out}/color.png --color bogus", 2,
       {"unknown --color 'bogus'"}, "color.png"},
      {"option_unknown_view", "render {in}/good.nc -o {out}/view.png --view bogus", 2,
       {"unknown --view 'bogus'"}, "view.png"},
      {"option_unknown_cmap", "render {in}/good.nc -o {out}/cmap.png --cmap bogus", 2,
       {"unknown colour map 'bogus'"}, "cmap.png"},
      {"option_lines_reversed_fit", "fit {in}/good.nc --lines 9-1", 2,
       {"good.nc", "line range '9-1' ends before it starts"}, ""},
      {"option_lines_reversed_intervals", "intervals {in}/good.nc --lines 9-1", 2,
       {"good.nc", "line range '9-1' ends before it starts"}, ""},
      {"option_lines_reversed_optimize", "optimize {in}/good.nc -o {out}/lines.nc --lines 9-1", 2,
       {"line range '9-1' ends before it starts"}, "lines.nc"},
      {"option_fit_tolerance_zero", "fit {in}/good.nc --lines 2-3 --tolerance 0", 2,
       {"--tolerance: 0 must be above 0"}, ""},
      {"option_dist_ratio_below_one", "intervals {in}/good.nc --dist-ratio 0.5", 2,
       {"--dist-ratio: 0.5 must be above 1"}, ""},
      {"option_locate_point_two_values", "locate {in}/ok.biip --point 1,2", 2,
       {"--point needs X,Y,Z", "'1,2'"}, ""},
      {"option_locate_sample_out_of_range", "locate {in}/ok.biip --sample 99", 2,
       {"ok.biip", "sample 99 is out of range"}, ""},
      {"option_unknown_surface", "export {in}/ok.biip --vtp {out}/surface.vtp --surface bogus", 2,
       {"unknown --surface 'bogus'"}, "surface.vtp"},
      {"option_unknown_sample", "sample bogus -o {out}/bogus.nc", 2,
       {"unknown sample 'bogus'"}, "bogus.nc"},
      {"missing_input_canon", "canon {in}/no_such.nc -o {out}/missing.txt", 2,
       {"no_such.nc", "cannot open"}, "missing.txt"},
      {"missing_input_info", "info {in}/no_such.biip -o {out}/missing.json", 2,
       {"no_such.biip", "No such file or directory"}, "missing.json"},
      {"missing_input_simulate", "simulate {in}/no_such.nc -o {out}/missing.biip", 2,
       {"no_such.nc"}, "missing.biip"},

      // Machine traces
      {"trace_partial_feedback", "import csv {in}/trace.csv --map x=x,y=y,z=z,fb_x=ax -o {out}/partial_fb.biip", 2,
       {"trace.csv", "fb_x, fb_y and fb_z together"}, "partial_fb.biip"},
      {"trace_time_not_finite", "import csv {in}/trace_time_inf.csv --map x=x,y=y,z=z,t=t -o {out}/t_inf.biip", 2,
       {"trace_time_inf.csv:3:", "time 'inf' is not finite"}, "t_inf.biip"},
      {"trace_too_many_columns", "import csv {in}/wide.csv --preset umich -o {out}/wide.biip", 2,
       {"wide.csv", "more than 247 extra channels", "'c247'"}, "wide.biip"},

      {"biip_time_nan", "info {in}/t_nan.biip", 2, {"t_nan.biip", "record 1: time t is not finite"}, ""},
      {"biip_time_backwards", "render {in}/t_backwards.biip -o {out}/t_back.png --size 64x48", 2,
       {"t_backwards.biip", "record 2: time t runs backwards"}, "t_back.png"},
      {"biip_time_still", "info {in}/t_still.biip", 2, {"t_still.biip", "time t stands still"}, ""},
      {"trace_time_backwards", "import csv {in}/trace_time_back.csv --map x=x,y=y,z=z,t=t -o {out}/t_back.biip", 2,
       {"trace_time_back.csv:4:", "runs backwards"}, "t_back.biip"},
      {"trace_time_still", "import csv {in}/trace_time_still.csv --map x=x,y=y,z=z,t=t -o {out}/t_still.biip", 2,
       {"trace_time_still.csv", "does not advance"}, "t_still.biip"},
      {"trace_line_negative", "import csv {in}/trace_line_neg.csv --map x=x,y=y,z=z,line=n -o {out}/l_neg.biip", 2,
       {"trace_line_neg.csv:3:", "line number '-1'"}, "l_neg.biip"},
      {"trace_line_fraction", "import csv {in}/trace_line_frac.csv --map x=x,y=y,z=z,line=n -o {out}/l_frac.biip", 2,
       {"trace_line_frac.csv:3:", "line number '3.7'"}, "l_frac.biip"},
      {"trace_line_huge", "import csv {in}/trace_line_huge.csv --map x=x,y=y,z=z,line=n -o {out}/l_huge.biip", 2,
       {"trace_line_huge.csv:3:", "line number '1e11'"}, "l_huge.biip"},
      {"machine_cycle_only", "simulate {in}/good.nc --machine {in}/m_cycle_only.json -o {out}/m_cycle.biip", 2,
       {"m_cycle_only.json", "axes.x.position_gain_1_s is too high for cycle_s"}, "m_cycle.biip"},
      {"machine_misspelled_key", "simulate {in}/good.nc --machine {in}/m_misspelled.json -o {out}/m_typo.biip", 2,
       {"m_misspelled.json", "unknown key \"rapid_mm_mn\"", "did you mean \"rapid_mm_min\""}, "m_typo.biip"},
      {"machine_misspelled_axis_key", "simulate {in}/good.nc --machine {in}/m_axis_misspelled.json -o {out}/m_typo2.biip", 2,
       {"m_axis_misspelled.json", "axes.z.max_jerk_mm_s3"}, "m_typo2.biip"},
      {"sts_assignment", "sts --surface x=1 -o {out}/flat.nc", 2, {"'='", "assigns"}, "flat.nc"},
      {"sts_compound_assignment", "sts --surface y+=2 -o {out}/flat2.nc", 2, {"'='"}, "flat2.nc"},
      {"sts_tiny_angle_step", "sts --surface toric --angle-step 1e-9 -o {out}/tiny_angle.nc", 2,
       {"--angle-step", "contact points, more than"}, "tiny_angle.nc"},
      {"sts_tiny_arc_step", "sts --surface toric --discretise arc --arc-step 1e-9 -o {out}/tiny_arc.nc", 2,
       {"--arc-step", "contact points, more than"}, "tiny_arc.nc"},
      {"sts_too_steep_for_height_step", "sts --surface x^25 -o {out}/steep.nc", 2,
       {"rises more than --height-step"}, "steep.nc"},
      {"sts_huge_samples", "sts --surface toric --samples 2000000000 -o {out}/many_samples.nc", 2,
       {"--samples must be at most"}, "many_samples.nc"},
      {"sts_huge_node_count", "sts --surface toric --uniform-nodes 999999999999 -o {out}/many_nodes.nc", 2,
       {"--uniform-nodes must be at most"}, "many_nodes.nc"},
      {"fit_absurd_tolerance", "fit {in}/good.nc --lines 2-3 --tolerance 1e-15", 2,
       {"--tolerance must be from 1e-06 to 10 mm"}, ""},
      {"machine_huge_file", "simulate {in}/good.nc --machine {in}/m_huge.json -o {out}/m_huge.biip", 2,
       {"m_huge.json", "a machine description is at most 1048576 bytes"}, "m_huge.biip"},

      // Outputs that cannot be written (canon documents exit code 1 for these)
      {"output_missing_dir_canon", "canon {in}/good.nc -o {out}/no_dir/a.txt", 2,
       {"no_dir/a.txt", "cannot write"}, "no_dir/a.txt"},
      {"output_missing_dir_simulate", "simulate {in}/good.nc -o {out}/no_dir/a.biip", 2,
       {"no_dir/a.biip", "cannot write"}, "no_dir/a.biip"},
      {"output_missing_dir_export", "export {in}/ts.biip --vtp {out}/no_dir/a.vtp", 2,
       {"no_dir/a.vtp", "cannot write"}, "no_dir/a.vtp"},
      {"output_dev_full_canon", "canon {in}/good.nc -o /dev/full", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
      {"output_dev_full_simulate", "simulate {in}/good.nc -o /dev/full", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
      {"output_dev_full_info", "info {in}/ok.biip -o /dev/full", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
      {"output_dev_full_export", "export {in}/ts.biip --vtp /dev/full", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
      {"output_dev_full_analyze", "analyze {in}/ts.nc {in}/ts.biip -o /dev/full", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
      {"output_dev_full_render", "render {in}/ts.nc {in}/ts.biip -o /dev/full --size 64x48", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
      {"output_dev_full_sample", "sample transition-surface -o /dev/full", 2,
       {"/dev/full", "No space left on device"}, "/dev/full"},
  };
  return rows;
}

void PrintTo(const Row& row, std::ostream* os) { *os << row.name; }

std::string expand(std::string s) {
  using Pair = std::pair<std::string, std::string>;
  for (const auto& [key, value] :
       {Pair{"{in}", inDir().string()}, Pair{"{out}", outDir().string()}}) {
    for (std::size_t at; (at = s.find(key)) != std::string::npos;) s.replace(at, key.size(), value);
  }
  return s;
}

class BadInput : public ::testing::TestWithParam<Row> {
 protected:
  static void SetUpTestSuite() { writeInputs(); }
  static void TearDownTestSuite() {  // the inputs include a 2 MB program and a 10 MB dump
    std::error_code ignored;
    fs::remove_all(inDir(), ignored);
    fs::remove_all(outDir(), ignored);
  }
};

// A program and dump with a real surface, for the commands that get as far as writing; made only
// for the rows that use them (each test may run in a process of its own).
void writeSurfaceInputs() {
  const auto ts = (inDir() / "ts.nc").string();
  if (fs::exists(inDir() / "ts.biip")) return;
  const auto made = runCli("sample transition-surface -o " + ts);
  ASSERT_EQ(made.exitCode, 0) << made.err;
  const auto sim = runCli("simulate " + ts + " -o " + (inDir() / "ts.biip").string());
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
}

TEST_P(BadInput, FailsCleanly) {
  const Row& row = GetParam();
  if (!row.skip.empty()) GTEST_SKIP() << row.skip;
  if (row.args.find("{in}/ts.") != std::string::npos) {
    writeSurfaceInputs();
    if (HasFatalFailure()) return;
  }
  const std::string args = expand(row.args);
  const auto r = runCli(args);
  SCOPED_TRACE("isurface-cli " + args + "\nstderr: " + r.err.substr(0, 2000));
  EXPECT_EQ(r.exitCode, row.exitCode);
  EXPECT_NE(r.err.find("error"), std::string::npos);
  for (const auto& s : row.mustContain) {
    EXPECT_NE(r.err.find(s), std::string::npos) << "missing: " << s;
  }
  if (!row.output.empty() && row.output.rfind("/dev/", 0) != 0) {
    const fs::path out = outDir() / row.output;
    EXPECT_FALSE(fs::exists(out)) << "output left behind: " << out;
    // Nor a temporary file beside it.
    if (fs::is_directory(out.parent_path())) {
      for (const auto& e : fs::directory_iterator(out.parent_path())) {
        EXPECT_NE(e.path().filename().string().rfind(out.filename().string() + ".tmp", 0), 0u)
            << "temporary file left behind: " << e.path();
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInput, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Row>& info) { return info.param.name; });

TEST(BadInputCatalogue, HasAtLeastFortyRows) { EXPECT_GE(catalogue().size(), 40u); }

// Inputs that look odd but are accepted on purpose: they must not be reported as errors.
TEST(BadInputCatalogue, AcceptedOddities) {
  fs::create_directories(inDir());
  fs::create_directories(outDir());
  writeBytes("really_empty.nc", "");
  writeBytes("unknown_m.nc", "G0 X0 Y0 Z0\nM77\nG1 X1 F100\n");
  const auto empty = runCli("canon " + (inDir() / "really_empty.nc").string());
  EXPECT_EQ(empty.exitCode, 0) << empty.err;
  EXPECT_TRUE(empty.out.empty());
  const auto m = runCli("canon " + (inDir() / "unknown_m.nc").string());
  EXPECT_EQ(m.exitCode, 0) << m.err;
  // Old Mac line ends: three lines, two moves (not one diagonal move).
  writeBytes("mac.nc", "G21 G90 G1 X10 F100\rY20\rM2\r");
  const auto mac = runCli("canon " + (inDir() / "mac.nc").string());
  EXPECT_EQ(mac.exitCode, 0) << mac.err;
  EXPECT_NE(mac.out.find("1 G1 10.0000 0.0000 0.0000"), std::string::npos) << mac.out;
  EXPECT_NE(mac.out.find("2 G1 10.0000 20.0000 0.0000"), std::string::npos) << mac.out;
  // A CSV saved with a UTF-8 byte order mark names its first column like any other.
  writeBytes("bom.csv", "\xEF\xBB\xBFx,y,z\n0,0,0\n1,0,0\n");
  const auto bom = runCli("import csv " + (inDir() / "bom.csv").string() + " --map x=x,y=y,z=z -o " +
                          (outDir() / "bom.biip").string());
  EXPECT_EQ(bom.exitCode, 0) << bom.err;
  // Metadata nested thousands deep is set aside with a warning: info stays short and alive.
  BiipSpec deep;
  deep.metadata = std::string(20000, '[') + std::string(20000, ']');
  deep.metadata = "{\"a\": " + deep.metadata + "}";
  writeBytes("meta_deep.biip", biip(deep));
  const auto info = runCli("info " + (inDir() / "meta_deep.biip").string());
  EXPECT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.err.find("nested"), std::string::npos) << info.err;
  EXPECT_LT(info.out.size(), 20000u);
}

}  // namespace
