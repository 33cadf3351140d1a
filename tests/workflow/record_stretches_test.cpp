// Stretches of a dump's records in one Trajectory: a thinned dump's close-up at the dump's own
// resolution, its speeds, accelerations and jerks those of the whole run at the same records.
#include <gtest/gtest.h>

#include "isurface/analysis/quantities.h"
#include "isurface/io/biip.h"
#include "isurface/workflow/record_stretches.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

TEST(recordStretches, EachStretchIsAPassWhoseValuesAreTheWholeRunsAtTheSameRecords) {
  const BiipReader reader(transitionDump());
  TrajectoryChannels channels;
  channels.feedback = false;
  const Trajectory whole = loadTrajectory(reader, {}, channels);
  const std::vector<RecordStretch> stretches = {{1000, 500}, {40'000, 301}, {2, 50}, {whole.size() - 20, 100}};
  for (const std::size_t every : {1u, 2u}) {
    channels.thinning = every;
    PassSet passes;
    const Trajectory part = loadRecordStretches(reader, stretches, channels, passes);
    ASSERT_EQ(passes.passes.size(), stretches.size());
    for (const Quantity q : {Quantity::Speed, Quantity::Acceleration, Quantity::Jerk}) {
      std::vector<float> wholeValues(whole.size()), partValues(part.size());
      sampleQuantityRange(q, whole, 0, whole.size(), wholeValues.data());
      sampleQuantityRange(q, part, 0, part.size(), partValues.data());
      for (std::size_t p = 0; p < stretches.size(); ++p) {
        const Pass& pass = passes.passes[p];
        const std::size_t end = std::min(whole.size(), stretches[p].first + stretches[p].count);
        EXPECT_EQ(pass.size(), (end - stretches[p].first + every - 1) / every) << p;
        for (std::size_t i = pass.begin; i < pass.end; ++i) {
          const std::size_t record = stretches[p].first + (i - pass.begin) * every;
          ASSERT_EQ(part.x[i], whole.x[record]) << p << " " << i;
          ASSERT_EQ(part.line[i], whole.line[record]);
          if (every == 1 && record >= 2 && record + 2 < whole.size()) {
            ASSERT_FLOAT_EQ(partValues[i], wholeValues[record]) << quantityInfo(q).label << " at record " << record;
          }
        }
      }
    }
  }
}
