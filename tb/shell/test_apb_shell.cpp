// SPDX-License-Identifier: MIT
// The APB register shell (rtl/acore_apb.v) around both tops, the pipelined one also folded,
// through one driver (tb/shell/shell_driver.hpp) and one suite parameterized over the registry's
// shell builds (Shell/Shell.*/apb, .../apb_serial, .../apb_fold2, ...):
//   - coefficient reloads every 1000 samples at full input rate under random output backpressure:
//     every output equals the bit-accurate model under the image the test committed before the
//     sample was taken, and carries that image's generation tag;
//   - the busy time of a commit against its closed form (docs/register-shell-guide.md, "Commit"),
//   and a
//     commit waiting for every sample the top can hold;
//   - in_ready low in reset; every single-bit flip of every shadow word refused by the CRC check,
//     and every single-bit flip of every active word found by the scrubber;
//   - the register map (ID and CONFIG against the parameters and the measured latency, reset
//     values, read/write of every register, W1C, IRQ) and the APB protocol (zero wait states,
//     PSLVERR cases, back-to-back transfers).
// Independent expectations: FixedModel (bit-accurate model), the model's zlib CRC-32
// (image_crc32), the tops' own public LATENCY/CYCLES, and the test's own record of when it
// committed. The RTL starts from a random state (randReset(2)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "cosim/cosim_stimuli.hpp"
#include "engine/fixed_model.hpp"
#include "shell/shell_driver.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

namespace sh = shell;

// The paper scenario's calibrated image in configuration c (the words the bench streams through).
RegImage paper_image_for(const DatapathConfig& c) {
  const Recording cal = test::paper_recording(4000, true);
  if (c.fourier_k == 0)
    return quantize(calibrate(cal, CalOptions{}), c, choose_in_scale(cal, c.in_w));
  return calibrate_image(cal, c, 1);  // the Fourier words fitted too
}

std::string show(const FixedSample& s) { return cosim::show(s); }

class Shell : public ::testing::TestWithParam<const RtlBuild*> {
 protected:
  bool serial() const { return GetParam()->serial; }
  // The build's configuration, its paper image and random images (cached per build).
  const DatapathConfig& cfg() const { return GetParam()->cfg; }
  const RegImage& paper_image() const {
    static std::map<const RtlBuild*, RegImage> cache;
    auto it = cache.find(GetParam());
    if (it == cache.end()) it = cache.emplace(GetParam(), paper_image_for(cfg())).first;
    return it->second;
  }
  RegImage random_image(std::mt19937_64& rng) const {
    return cosim::random_image(cosim::identity_image(cfg()), rng, false);
  }
  // CRC bits per clock of the build (the shell's default for each top: 4 around a folded one).
  int crc_w() const { return serial() ? 8 : cfg().fold > 1 ? 4 : 16; }
};

// Reads STATUS until the scrubber has completed `passes` more passes than `from`.
uint32_t wait_passes(ShellDriver& d, uint32_t from, uint32_t passes) {
  for (int n = 0; n < 1000000; ++n) {
    const uint32_t p = d.read(sh::kScrubPasses);
    if (static_cast<uint16_t>(p - from) >= passes) return p;
  }
  throw CheckFailed("the scrubber does not complete passes");
}

TEST_P(Shell, IdAndConfigMatchTheParametersAndTheMeasuredLatency) {
  ShellDriver d(*GetParam());
  d.reset();
  d.set_window(StatusWindow::defaults(cfg()));
  const DatapathConfig& c = cfg();
  EXPECT_EQ(d.read(sh::kId), sh::kIdValue);
  const uint32_t c0 = d.read(sh::kConfig0), c1 = d.read(sh::kConfig1), c2 = d.read(sh::kConfig2),
                 c3 = d.read(sh::kConfig3);
  // A field of a register value (tb/shell/shell_regs.hpp: mask in place, shift).
  const auto field = [](uint32_t v, uint32_t mask, int shift) { return (v & mask) >> shift; };
  EXPECT_EQ(field(c0, sh::kConfig0DegreeMask, sh::kConfig0DegreeShift),
            static_cast<uint32_t>(c.degree));
  EXPECT_EQ(field(c0, sh::kConfig0RegionsMask, sh::kConfig0RegionsShift),
            static_cast<uint32_t>(c.regions));
  EXPECT_EQ(field(c0, sh::kConfig0CorrectionMask, sh::kConfig0CorrectionShift),
            static_cast<uint32_t>(c.correction));
  EXPECT_EQ((c0 & sh::kConfig0Xcenter) != 0, c.xcenter != 0);
  EXPECT_EQ((c0 & sh::kConfig0Zero) != 0, c.zero_word != 0);
  EXPECT_EQ((c0 & sh::kConfig0Serial) != 0, serial());
  EXPECT_EQ(field(c0, sh::kConfig0FoldMask, sh::kConfig0FoldShift), static_cast<uint32_t>(c.fold));
  EXPECT_EQ(field(c0, sh::kConfig0KMask, sh::kConfig0KShift), static_cast<uint32_t>(c.iterations));
  EXPECT_EQ(field(c1, sh::kConfig1WordsMask, sh::kConfig1WordsShift),
            static_cast<uint32_t>(c.words()));
  EXPECT_EQ(field(c1, sh::kConfig1FourierKMask, sh::kConfig1FourierKShift),
            static_cast<uint32_t>(c.fourier_k));
  EXPECT_EQ(field(c1, sh::kConfig1RegWMask, sh::kConfig1RegWShift), static_cast<uint32_t>(c.reg_w));
  const uint32_t latency = field(c2, sh::kConfig2LatencyMask, sh::kConfig2LatencyShift),
                 cycles = field(c2, sh::kConfig2CyclesMask, sh::kConfig2CyclesShift);
  EXPECT_EQ(latency, d.top_param("LATENCY"));
  // Clocks per sample: the serial core's own count, FOLD for acore_top (1: pipelined).
  EXPECT_EQ(cycles, d.top_param("CYCLES"));
  if (!serial()) EXPECT_EQ(cycles, static_cast<uint32_t>(c.fold));
  EXPECT_EQ(field(c3, sh::kConfig3InWMask, sh::kConfig3InWShift), static_cast<uint32_t>(c.in_w));
  EXPECT_EQ(field(c3, sh::kConfig3AngleWMask, sh::kConfig3AngleWShift),
            static_cast<uint32_t>(c.angle_w));
  EXPECT_EQ(field(c3, sh::kConfig3MagWMask, sh::kConfig3MagWShift),
            static_cast<uint32_t>(c.s_w + 2));
  EXPECT_EQ(field(c3, sh::kConfig3CrcWMask, sh::kConfig3CrcWShift), static_cast<uint32_t>(crc_w()));
  // LATENCY measured through the shell: the output of a lone sample comes LATENCY clocks after it
  // was taken.
  d.load_and_commit(paper_image());
  d.stream(cosim::paper_codes(paper_image(), 1), 0.0, 0.0, 1);
  d.drain();
  ASSERT_EQ(d.outputs().size(), 1u);
  EXPECT_EQ(d.outputs()[0].cycle - d.accept_cycles()[0], latency);
  EXPECT_EQ(d.outputs()[0].sample,
            FixedModel(paper_image()).step(cosim::paper_codes(paper_image(), 1)[0]));
}

TEST_P(Shell, ReloadEvery1000SamplesAtFullRateWithBackpressure) {
  // The host loads image g+1 into the shadow while image g is in use, and commits it once 1000
  // more samples have been taken; the input is valid every clock, out_ready is low 30 % of the
  // clocks. Sample j must come out as FixedModel(image g).step(in[j]), g = the number of commits
  // the test completed before the clock that took j, minus one, with the tag g's bank bit.
  const int n_images = serial() ? 5 : 20;
  const size_t per_image = 1000;
  std::mt19937_64 rng(serial() ? 71 : 17);
  std::vector<RegImage> images;
  for (int g = 0; g < n_images; ++g)
    images.push_back(g % 3 == 0   ? paper_image()
                     : g % 3 == 1 ? cosim::identity_image(cfg())
                                  : random_image(rng));
  // Random images with random offsets differ from their neighbours; make the paper image's
  // repeats differ too (a changed offset), so that no two consecutive images agree.
  for (int g = 3; g < n_images; g += 3) images[g].set_signed(cfg().addr_offset(0), 37 * g);
  std::vector<ChannelCodes> in;
  for (int g = 0; g < n_images; ++g) {
    const auto part = g % 2 ? cosim::random_codes(rng, per_image, cfg().in_w)
                            : cosim::paper_codes(paper_image(), per_image);
    in.insert(in.end(), part.begin(), part.end());
  }
  // Consecutive images must give different results on most samples, or a mix would go unseen.
  for (int g = 1; g < n_images; ++g) {
    const FixedModel a(images[g - 1]), b(images[g]);
    size_t differ = 0;
    for (size_t j = g * per_image; j < g * per_image + 200; ++j)
      differ += !(a.step(in[j]) == b.step(in[j]));
    EXPECT_GT(differ, 150u) << "images " << g - 1 << " and " << g << " agree too often";
  }

  ShellDriver d(*GetParam(), "", 2, 5);
  d.reset();
  d.set_window(StatusWindow::defaults(cfg()));  // the models' LOS/DOS window
  d.set_ctrl(sh::kCtrlScrub | sh::kCtrlCrcCheck);
  std::vector<uint64_t> commit_cycle;  // the clock whose edge took each CTRL.COMMIT write
  ASSERT_EQ(d.load_and_commit(images[0]) & (sh::kStatusCrcShadow | sh::kStatusBusy), 0u);
  commit_cycle.push_back(d.cycles());
  d.write(sh::kStatus, sh::kStatusW1cMask);
  d.stream(in, 0.0, 0.3, 99);

  // The host program, advanced one clock at a time beside the stream.
  enum { kLoad, kWaitCount, kWaitCommit, kPoll, kDone } state = kLoad;
  int g = 0;
  std::shared_ptr<const ApbTransfer> last;
  while (d.outputs().size() < in.size()) {
    switch (state) {
      case kLoad:
        for (size_t a = 0; a < images[g + 1].words.size(); ++a)
          d.post(true, sh::kCoef + 4 * static_cast<uint32_t>(a),
                 static_cast<uint32_t>(images[g + 1].words[a]));
        d.post(true, sh::kCrcExpected, image_crc32(images[g + 1]));
        state = kWaitCount;
        break;
      case kWaitCount:
        if (d.apb_idle() && d.accepted() >= per_image * (g + 1)) {
          last = d.post(true, sh::kCtrl, d.ctrl() | sh::kCtrlCommit);
          state = kWaitCommit;
        }
        break;
      case kWaitCommit:
        if (last->done) {
          ASSERT_FALSE(last->slverr) << "commit " << g + 1;
          commit_cycle.push_back(last->cycle);
          last = d.post(false, sh::kStatus);
          state = kPoll;
        }
        break;
      case kPoll:
        if (last->done) {
          if (last->rdata & sh::kStatusBusy) {
            last = d.post(false, sh::kStatus);
          } else {
            EXPECT_EQ(last->rdata & (sh::kStatusCrcShadow | sh::kStatusCrcActive), 0u)
                << "commit " << g + 1;
            EXPECT_NE(last->rdata & sh::kStatusDone, 0u);
            EXPECT_EQ((last->rdata & sh::kStatusBank) != 0, (g + 2) % 2 == 1);
            d.post(true, sh::kStatus, sh::kStatusDone);
            ++g;
            state = g + 1 < n_images ? kLoad : kDone;
          }
        }
        break;
      case kDone:
        break;
    }
    d.tick();
    ASSERT_LT(d.cycles(), 50'000'000u);
  }
  ASSERT_EQ(g, n_images - 1);
  ASSERT_EQ(d.accept_cycles().size(), in.size());

  std::vector<FixedModel> models;
  for (const RegImage& img : images) models.emplace_back(img);
  size_t mismatches = 0, tag_errors = 0;
  std::string first;
  for (size_t j = 0; j < in.size(); ++j) {
    // The image in use: commits strictly before the clock that took the sample.
    const int img = static_cast<int>(std::lower_bound(commit_cycle.begin(), commit_cycle.end(),
                                                      d.accept_cycles()[j]) -
                                     commit_cycle.begin()) -
                    1;
    const bool tag = (img + 1) % 2 == 1;  // bank 0 after reset, flipped by every applied commit
    const ShellOutput& o = d.outputs()[j];
    const FixedSample m = models[img].step(in[j]);
    tag_errors += o.tag != tag;
    if (!(o.sample == m)) {
      if (first.empty())
        first = "sample " + std::to_string(j) + " (image " + std::to_string(img) + "): rtl " +
                show(o.sample) + ", model " + show(m);
      ++mismatches;
    }
  }
  const uint32_t st = d.read(sh::kStatus);
  std::printf(
      "%s: %zu samples, %d images, %zu mismatches, %zu tag errors, %llu clocks; status 0x%x, %u "
      "scrub passes\n",
      GetParam()->name.c_str(), in.size(), n_images, mismatches, tag_errors,
      static_cast<unsigned long long>(d.cycles()), st, d.read(sh::kScrubPasses));
  EXPECT_EQ(mismatches, 0u) << first;
  EXPECT_EQ(tag_errors, 0u);
  // The scrubber ran beside the stream and never mistook a read: no CRC_ACTIVE.
  EXPECT_EQ(st & sh::kStatusCrcActive, 0u);
  EXPECT_GT(d.read(sh::kScrubPasses), 0u);
  EXPECT_EQ(d.apb_stats().wait_states + d.apb_stats().stray_slverr + d.apb_stats().stray_prdata,
            0u);
}

TEST_P(Shell, CommitBusyTimeIsItsClosedForm) {
  // busy = max(6 + P + WORDS 32/CRC_W, drain) + WORDS + 4 clocks from the clock of the CTRL write:
  // request 1, INIT 1, CHECK until both the CRC pass and its check (4 + P + WORDS 32/CRC_W clocks;
  // P = 2 when CRC_W >= 16 registers the word and splits the fold over two clocks) and the drain
  // are done, the drain ending one clock after the last sample in flight has left; STREAM
  // WORDS + 2, SETTLE 2.
  // Measured as the clocks with in_ready low (out_ready high throughout).
  const uint32_t words = cfg().words(), steps = 32 / crc_w(),
                 pass = 6 + 2 * (crc_w() >= 16) + words * steps;
  ShellDriver d(*GetParam());
  d.reset();
  d.set_window(StatusWindow::defaults(cfg()));
  ASSERT_EQ(d.load_and_commit(paper_image()) & sh::kStatusCrcShadow, 0u);
  const uint32_t latency = d.read(sh::kConfig2) & sh::kConfig2LatencyMask;
  // Idle: nothing in flight.
  {
    const auto t = d.post(true, sh::kCtrl, d.ctrl() | sh::kCtrlCommit);
    while (!t->done) d.tick();
    uint64_t busy = 0;
    while (!d.pins().in_ready()) {
      d.tick();
      ++busy;
    }
    const uint64_t expect = pass + words + 4;
    std::printf("%s: commit with an idle core: %llu clocks busy (closed form %llu)\n",
                GetParam()->name.c_str(), static_cast<unsigned long long>(busy),
                static_cast<unsigned long long>(expect));
    EXPECT_EQ(busy, expect);
  }
  // Streaming at full rate: the commit also waits for the samples in flight.
  d.stream(cosim::paper_codes(paper_image(), 3000), 0.0, 0.0, 3);
  uint64_t lost = 0, commit_at = 0;
  bool committed = false, resumed = false;
  std::shared_ptr<const ApbTransfer> t;
  while (d.outputs().size() < d.queued()) {
    if (!t && d.accepted() >= 1000) t = d.post(true, sh::kCtrl, d.ctrl() | sh::kCtrlCommit);
    d.tick();
    if (t && t->done && !committed) {
      committed = true;
      commit_at = t->cycle;
    }
    if (committed && !resumed) {
      d.pins().eval(true);
      if (d.pins().in_ready())
        resumed = true;
      else
        ++lost;
    }
  }
  // The last sample taken at or before the commit clock, and when it left.
  const auto& acc = d.accept_cycles();
  const size_t last = std::upper_bound(acc.begin(), acc.end(), commit_at) - acc.begin() - 1;
  const uint64_t drain = d.outputs()[last].cycle + 1 - commit_at;
  const uint64_t expect = std::max<uint64_t>(pass, drain) + words + 4;
  std::printf(
      "%s: commit while streaming: %llu input clocks lost (drain %llu, closed form %llu; %u words, "
      "LATENCY %u, "
      "CRC %u bits/clock)\n",
      GetParam()->name.c_str(), static_cast<unsigned long long>(lost),
      static_cast<unsigned long long>(drain), static_cast<unsigned long long>(expect), words,
      latency, crc_w());
  EXPECT_EQ(lost, expect);
  // Around acore_top the last sample leaves LATENCY clocks after it was taken (out_ready high, the
  // folded top's FIFO empty); the drain ends the clock after. A folded top takes a sample every
  // FOLD clocks, so the last one may precede the commit by up to FOLD - 1 clocks.
  if (!serial()) {
    EXPECT_EQ(drain, acc[last] + latency + 1 - commit_at);
    EXPECT_LT(commit_at - acc[last], static_cast<uint64_t>(cfg().fold));
  }
  // Every output still matches the (unchanged) image.
  const FixedModel m(paper_image());
  const auto in = cosim::paper_codes(paper_image(), 3000);
  size_t bad = 0;
  for (size_t j = 0; j < in.size(); ++j) bad += !(d.outputs()[j].sample == m.step(in[j]));
  EXPECT_EQ(bad, 0u);
}

TEST_P(Shell, CommitWaitsForEverySampleTheTopHolds) {
  // The output held (out_ready low), the top takes as many samples as it can hold: one per
  // pipeline stage (LATENCY), the folded top's output FIFO (256, one block RAM deep), the serial
  // core's one in work and one result waiting. A commit then waits for all of them to leave: they
  // come out computed with the old image and with its tag, the samples after the commit with the
  // new one. A drain counter too narrow for the top would let the commit through early (the
  // folded top's 256 samples would leave with the new tag).
  const RegImage a = paper_image();
  std::mt19937_64 rng(41);
  const RegImage b = random_image(rng);
  ShellDriver d(*GetParam(), "", 2, 31);
  d.reset();
  d.set_window(StatusWindow::defaults(cfg()));
  ASSERT_EQ(d.load_and_commit(a) & sh::kStatusCrcShadow, 0u);  // tag 1
  const uint32_t c2 = d.read(sh::kConfig2);
  const uint32_t latency = c2 & sh::kConfig2LatencyMask,
                 cycles = (c2 & sh::kConfig2CyclesMask) >> sh::kConfig2CyclesShift;
  const size_t capacity = serial() ? 2 : cfg().fold == 1 ? latency : 256;
  const auto in = cosim::paper_codes(a, capacity + 100);
  d.stream(in, 0.0, 1.0, 5);
  // Enough clocks to take every sample the top can hold, and more.
  d.ticks(static_cast<int>((capacity + 4) * cycles + 2 * latency + 100));
  EXPECT_EQ(d.accepted(), capacity);
  EXPECT_EQ(d.outputs().size(), 0u);
  d.write_shadow(b);
  ASSERT_FALSE(d.write(sh::kCrcExpected, image_crc32(b)));
  ASSERT_FALSE(d.write(sh::kCtrl, d.ctrl() | sh::kCtrlCrcCheck | sh::kCtrlCommit));
  d.ticks(2000);
  EXPECT_NE(d.read(sh::kStatus) & sh::kStatusBusy, 0u) << "the commit did not wait";
  EXPECT_EQ(d.accepted(), capacity);
  // Release the output: the held samples leave, the commit completes, the rest follows.
  d.stream({}, 0.0, 0.0, 6);
  d.drain();
  const uint32_t st = d.read(sh::kStatus);
  EXPECT_EQ(st & (sh::kStatusBusy | sh::kStatusCrcShadow | sh::kStatusBank), 0u);
  const FixedModel ma(a), mb(b);
  size_t bad = 0, tag_errors = 0;
  for (size_t j = 0; j < in.size(); ++j) {
    const bool old = j < capacity;
    bad += !(d.outputs()[j].sample == (old ? ma : mb).step(in[j]));
    tag_errors += d.outputs()[j].tag != old;
  }
  std::printf("%s: %zu samples held through a commit (capacity), %zu mismatches, %zu tag errors\n",
              GetParam()->name.c_str(), capacity, bad, tag_errors);
  EXPECT_EQ(bad, 0u);
  EXPECT_EQ(tag_errors, 0u);
}

TEST_P(Shell, InReadyIsLowInResetAndNothingIsTaken) {
  ShellDriver d(*GetParam(), "", 2, 9);
  d.reset();
  d.load_and_commit(paper_image());
  // Reset values the window (MAG_LO = 0, MAG_HI = all ones): the model's never flags either.
  const StatusWindow open{0, (int64_t{1} << (cfg().s_w + 2)) - 1};
  bool in_reset = false;
  size_t ready_in_reset = 0;
  d.on_clock([&] { ready_in_reset += in_reset && d.pins().in_ready(); });
  // Samples offered (in_valid high) while rst_i is high: in_ready stays low, nothing is taken.
  const auto in = cosim::paper_codes(paper_image(), 1500);
  d.stream(in, 0.0, 0.2, 4);
  in_reset = true;
  d.set_reset(true);
  d.ticks(20);
  EXPECT_EQ(d.accepted(), 0u);
  d.set_reset(false);
  in_reset = false;
  // Reset in mid-stream: in_ready falls with rst_i; the samples in flight are dropped.
  while (d.accepted() < 700) d.tick();
  const size_t accepted_at_reset = d.accepted(), emitted_at_reset = d.outputs().size();
  in_reset = true;
  d.set_reset(true);
  EXPECT_FALSE(d.pins().in_ready());
  d.ticks(5);
  d.set_reset(false);
  in_reset = false;
  EXPECT_FALSE(d.pins().out_valid());
  EXPECT_EQ(d.accepted(), accepted_at_reset);
  EXPECT_EQ(ready_in_reset, 0u);
  // Reset clears the shell's state, not the top's words: the stream goes on with the same image,
  // tag 0 (no commit since reset), from the first sample not taken.
  EXPECT_EQ(d.read(sh::kStatus), 0u);
  d.drain(emitted_at_reset + (in.size() - accepted_at_reset), 1'000'000);
  d.ticks(3 * d.top_param("LATENCY"));  // and no output more
  const FixedModel m(paper_image(), open);
  size_t bad = 0;
  const auto& out = d.outputs();
  for (size_t k = 0; k < out.size(); ++k) {
    const size_t j = k < emitted_at_reset ? k : accepted_at_reset + (k - emitted_at_reset);
    bad += !(out[k].sample == m.step(in[j])) || out[k].tag;
  }
  EXPECT_EQ(out.size(), emitted_at_reset + (in.size() - accepted_at_reset));
  EXPECT_EQ(bad, 0u);
}

TEST_P(Shell, EverySingleBitFlipOfTheShadowIsRefusedByTheCrc) {
  const RegImage img = paper_image();
  const uint32_t crc = image_crc32(img);
  ShellDriver d(*GetParam());
  d.reset();
  d.set_window(StatusWindow::defaults(cfg()));
  uint32_t st = d.load_and_commit(img);
  ASSERT_EQ(st & (sh::kStatusCrcShadow | sh::kStatusBusy), 0u);
  ASSERT_NE(st & sh::kStatusBank, 0u);
  EXPECT_EQ(d.read(sh::kCrcShadow), crc);
  EXPECT_EQ(d.read(sh::kCrcRef), crc);
  size_t refused = 0, crc_wrong = 0, applied = 0;
  for (int a = 0; a < cfg().words(); ++a) {
    for (int b = 0; b < cfg().reg_w; ++b) {
      RegImage bad = img;
      bad.words[a] ^= uint64_t{1} << b;
      ASSERT_FALSE(d.write(sh::kCoef + 4 * a, static_cast<uint32_t>(bad.words[a])));
      st = d.commit(true, crc);
      refused += (st & sh::kStatusCrcShadow) && (st & sh::kStatusDone);
      applied += !(st & sh::kStatusBank);
      // The shell's CRC of the flipped shadow is zlib's.
      crc_wrong += d.read(sh::kCrcShadow) != image_crc32(bad);
      d.write(sh::kStatus, sh::kStatusW1cMask);
    }
    d.write(sh::kCoef + 4 * a, static_cast<uint32_t>(img.words[a]));
  }
  const size_t flips = static_cast<size_t>(cfg().words()) * cfg().reg_w;
  std::printf("%s: %zu single-bit flips of the shadow, %zu refused\n", GetParam()->name.c_str(),
              flips, refused);
  EXPECT_EQ(refused, flips);
  EXPECT_EQ(applied, 0u);
  EXPECT_EQ(crc_wrong, 0u);
  EXPECT_EQ(d.read(sh::kCrcRef), crc);
  // The active image never changed: samples still match it, with the first commit's tag.
  const auto in = cosim::paper_codes(img, 300);
  d.stream(in, 0.1, 0.1, 2);
  d.drain();
  const FixedModel m(img);
  size_t bad = 0;
  for (size_t j = 0; j < in.size(); ++j)
    bad += !(d.outputs()[j].sample == m.step(in[j])) || !d.outputs()[j].tag;
  EXPECT_EQ(bad, 0u);
  // A wrong CRC_EXPECTED refuses the right image too, and without the check the commit applies.
  st = d.commit(true, crc ^ 1);
  EXPECT_NE(st & sh::kStatusCrcShadow, 0u);
  EXPECT_NE(st & sh::kStatusBank, 0u);
  d.write(sh::kStatus, sh::kStatusW1cMask);
  st = d.commit(false, 0);
  EXPECT_EQ(st & sh::kStatusCrcShadow, 0u);
  EXPECT_EQ(st & sh::kStatusBank, 0u);
}

TEST_P(Shell, EverySingleBitFlipOfTheActiveWordsIsFoundByTheScrubber) {
  const RegImage img = paper_image();
  const uint32_t crc = image_crc32(img);
  ShellDriver d(*GetParam());
  d.reset();
  // Before any commit the scrubber reads but has nothing to compare with.
  EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusRefValid, 0u);
  ASSERT_EQ(d.load_and_commit(img) & sh::kStatusCrcShadow, 0u);
  EXPECT_NE(d.read(sh::kStatus) & sh::kStatusRefValid, 0u);
  uint32_t p = wait_passes(d, d.read(sh::kScrubPasses), 2);
  EXPECT_EQ(d.read(sh::kCrcScrub), crc);
  EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusCrcActive, 0u);
  size_t found = 0, crc_wrong = 0, false_alarms = 0;
  for (int a = 0; a < cfg().words(); ++a) {
    for (int b = 0; b < cfg().reg_w; ++b) {
      d.flip_active_bit(a, b);
      // A pass under way may have read the word before the upset: two passes see it for sure.
      p = wait_passes(d, d.read(sh::kScrubPasses), 2);
      found += (d.read(sh::kStatus) & sh::kStatusCrcActive) != 0;
      RegImage bad = img;
      bad.words[a] ^= uint64_t{1} << b;
      crc_wrong += d.read(sh::kCrcScrub) != image_crc32(bad);
      d.flip_active_bit(a, b);
      p = wait_passes(d, d.read(sh::kScrubPasses), 2);
      d.write(sh::kStatus, sh::kStatusCrcActive);
      false_alarms += (d.read(sh::kStatus) & sh::kStatusCrcActive) != 0;
    }
  }
  const size_t flips = static_cast<size_t>(cfg().words()) * cfg().reg_w;
  std::printf("%s: %zu single-bit upsets of the active words, %zu found\n",
              GetParam()->name.c_str(), flips, found);
  EXPECT_EQ(found, flips);
  EXPECT_EQ(crc_wrong, 0u);
  EXPECT_EQ(false_alarms, 0u);
  // While samples flow (the serial core serves the scrubber's reads only between samples): a few
  // upsets, each found, and none without an upset.
  const auto in = cosim::paper_codes(img, serial() ? 1200 : 20000);
  d.stream(in, 0.0, 0.2, 8);
  for (int k = 0; k < 3; ++k) {
    const int a = (17 * k + 5) % cfg().words(), b = (5 * k + 3) % cfg().reg_w;
    d.flip_active_bit(a, b);
    p = wait_passes(d, d.read(sh::kScrubPasses), 2);
    EXPECT_NE(d.read(sh::kStatus) & sh::kStatusCrcActive, 0u) << "word " << a << " bit " << b;
    d.flip_active_bit(a, b);
    p = wait_passes(d, d.read(sh::kScrubPasses), 2);
    d.write(sh::kStatus, sh::kStatusCrcActive);
    EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusCrcActive, 0u);
  }
  EXPECT_GT(d.accepted(), 0u);
  EXPECT_LT(d.accepted(), in.size());  // the checks above ran while samples were still flowing
  (void)p;
}

TEST_P(Shell, ResetValuesAndReadWriteOfEveryRegister) {
  ShellDriver d(*GetParam(), "", 2, 13);
  d.reset();
  const uint32_t mag_mask = (uint32_t{1} << (cfg().s_w + 2)) - 1,
                 reg_mask = (uint32_t{1} << cfg().reg_w) - 1;
  EXPECT_EQ(d.read(sh::kCtrl), sh::kCtrlScrub);
  EXPECT_EQ(d.read(sh::kStatus), 0u);
  EXPECT_EQ(d.read(sh::kIrq), 0u);
  EXPECT_EQ(d.read(sh::kMagLo), 0u);
  EXPECT_EQ(d.read(sh::kMagHi), mag_mask);
  EXPECT_EQ(d.read(sh::kCrcExpected), 0u);
  EXPECT_FALSE(d.pins().irq());
  // The scrubber runs from reset (SCRUB = 1); a pass over the idle core's words takes (polled
  // every two clocks):
  const uint32_t p1 = wait_passes(d, d.read(sh::kScrubPasses), 1);
  const uint64_t t1 = d.cycles();
  wait_passes(d, p1, 4);
  std::printf("%s: a scrubber pass takes %.1f clocks (idle core)\n", GetParam()->name.c_str(),
              (d.cycles() - t1) / 4.0);
  std::mt19937_64 rng(21);
  for (int k = 0; k < 20; ++k) {
    const uint32_t v = static_cast<uint32_t>(rng());
    EXPECT_FALSE(d.write(sh::kMagLo, v));
    EXPECT_EQ(d.read(sh::kMagLo), v & mag_mask);
    EXPECT_FALSE(d.write(sh::kMagHi, ~v));
    EXPECT_EQ(d.read(sh::kMagHi), ~v & mag_mask);
    EXPECT_FALSE(d.write(sh::kCrcExpected, v));
    EXPECT_EQ(d.read(sh::kCrcExpected), v);
    // CTRL: COMMIT (bit 0) left out, CLEAR reads 0; CRC_CHECK, SCRUB and IRQ_EN read back.
    const uint32_t c = v & ~sh::kCtrlCommit;
    EXPECT_FALSE(d.write(sh::kCtrl, c));
    EXPECT_EQ(d.read(sh::kCtrl), c & sh::kCtrlReadMask);
  }
  d.write(sh::kCtrl, sh::kCtrlScrub);
  // The shadow window: every word, upper bits ignored.
  std::vector<uint32_t> w(cfg().words());
  for (int a = 0; a < cfg().words(); ++a) {
    w[a] = static_cast<uint32_t>(rng());
    EXPECT_FALSE(d.write(sh::kCoef + 4 * a, w[a]));
  }
  for (int a = 0; a < cfg().words(); ++a)
    EXPECT_EQ(d.read(sh::kCoef + 4 * a), w[a] & reg_mask) << a;
  // Read-only registers: a write is an error and changes nothing.
  for (const uint32_t r :
       {sh::kId, sh::kConfig0, sh::kConfig1, sh::kConfig2, sh::kConfig3, sh::kIrq, sh::kCrcShadow,
        sh::kCrcRef, sh::kCrcScrub, sh::kScrubPasses}) {
    const uint32_t before = d.read(r);
    EXPECT_TRUE(d.write(r, ~before)) << std::hex << r;
    if (r != sh::kScrubPasses && r != sh::kCrcScrub) EXPECT_EQ(d.read(r), before) << std::hex << r;
  }
  EXPECT_EQ(d.apb_stats().wait_states + d.apb_stats().stray_slverr + d.apb_stats().stray_prdata,
            0u);
}

TEST_P(Shell, StickyStatusW1CAndIrq) {
  ShellDriver d(*GetParam(), "", 2, 17);
  d.reset();
  std::mt19937_64 rng(23);
  // Sticky OVF/LOS/DOS are the OR of the flags of the outputs delivered since the last clear.
  for (int k = 0; k < (serial() ? 4 : 10); ++k) {
    const RegImage img = k % 2 ? random_image(rng) : paper_image();
    const int64_t span = int64_t{1} << (cfg().s_w + 1);
    const int64_t a = static_cast<int64_t>(rng() % span), b = static_cast<int64_t>(rng() % span);
    const StatusWindow win{std::min(a, b), std::max(a, b)};
    d.set_window(win);
    d.load_and_commit(img);
    d.write(sh::kCtrl, d.ctrl() | sh::kCtrlClear);
    EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusW1cMask, 0u);
    const auto in =
        k % 2 ? cosim::random_codes(rng, 300, cfg().in_w) : cosim::paper_codes(img, 300);
    const size_t first = d.outputs().size();
    d.stream(in, 0.2, 0.2, k);
    d.drain();
    const FixedModel m(img, win);
    uint32_t flags = 0;
    size_t bad = 0;
    for (size_t j = 0; j < in.size(); ++j) {
      const FixedSample s = m.step(in[j]);
      bad += !(d.outputs()[first + j].sample == s);
      flags |= (s.ovf ? sh::kStatusOvf : 0) | (s.los ? sh::kStatusLos : 0) |
               (s.dos ? sh::kStatusDos : 0);
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusW1cMask, flags) << k;
  }
  // W1C: one bit at a time; zeros and the live bits change nothing.
  d.set_window(StatusWindow{int64_t{1} << cfg().s_w, 0});  // every sample both LOS and DOS
  d.write(sh::kCtrl, d.ctrl() | sh::kCtrlClear);
  d.load_and_commit(paper_image());  // DONE
  d.stream(cosim::paper_codes(paper_image(), 20), 0.0, 0.0, 1);
  d.drain();
  const uint32_t set = sh::kStatusLos | sh::kStatusDos | sh::kStatusDone;
  const uint32_t live = d.read(sh::kStatus) & ~sh::kStatusW1cMask;
  EXPECT_EQ(live & sh::kStatusRefValid, sh::kStatusRefValid);
  EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusW1cMask, set);
  d.write(sh::kStatus, 0);
  EXPECT_EQ(d.read(sh::kStatus), set | live);
  d.write(sh::kStatus, sh::kStatusBusy | sh::kStatusBank | sh::kStatusRefValid);
  EXPECT_EQ(d.read(sh::kStatus), set | live);
  // IRQ = STATUS & IRQ_EN; irq_o = |IRQ (pins after the last clock).
  for (const uint32_t en : {0u, sh::kStatusDone, sh::kStatusLos | sh::kStatusOvf,
                            sh::kStatusOvf | sh::kStatusCrcShadow, sh::kStatusW1cMask}) {
    d.set_ctrl(sh::kCtrlScrub | (en << sh::kCtrlIrqEnShift));
    EXPECT_EQ(d.read(sh::kIrq), en & set) << en;
    EXPECT_EQ(d.pins().irq(), (en & set) != 0) << en;
  }
  d.write(sh::kStatus, sh::kStatusLos);
  EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusW1cMask, sh::kStatusDos | sh::kStatusDone);
  EXPECT_EQ(d.read(sh::kIrq), sh::kStatusDos | sh::kStatusDone);
  d.write(sh::kStatus, sh::kStatusDone);
  EXPECT_EQ(d.read(sh::kIrq), sh::kStatusDos);
  EXPECT_TRUE(d.pins().irq());
  d.write(sh::kCtrl, d.ctrl() | sh::kCtrlClear);
  EXPECT_EQ(d.read(sh::kStatus) & sh::kStatusW1cMask, 0u);
  EXPECT_EQ(d.read(sh::kIrq), 0u);
  EXPECT_FALSE(d.pins().irq());
  // A commit's DONE raises the interrupt when enabled.
  d.set_ctrl(sh::kCtrlScrub | (sh::kStatusDone << sh::kCtrlIrqEnShift));
  d.commit(false, 0);
  EXPECT_TRUE(d.pins().irq());
  EXPECT_EQ(d.read(sh::kIrq), sh::kStatusDone);
}

TEST_P(Shell, ApbProtocolErrorsAndBackToBackTransfers) {
  ShellDriver d(*GetParam(), "", 2, 29);
  d.reset();
  // Every word address of the 4 KiB space: reads succeed exactly on the map.
  const std::vector<uint32_t> regs = {sh::kId,      sh::kConfig0,  sh::kConfig1,     sh::kConfig2,
                                      sh::kConfig3, sh::kCtrl,     sh::kStatus,      sh::kIrq,
                                      sh::kMagLo,   sh::kMagHi,    sh::kCrcExpected, sh::kCrcShadow,
                                      sh::kCrcRef,  sh::kCrcScrub, sh::kScrubPasses};
  size_t wrong = 0, nonzero_on_error = 0;
  for (uint32_t addr = 0; addr < sh::kAddrSpace; addr += 4) {
    const bool mapped =
        std::count(regs.begin(), regs.end(), addr) ||
        (addr >= sh::kCoef && addr < sh::kCoef + 4 * static_cast<uint32_t>(cfg().words()));
    bool err = false;
    const uint32_t v = d.read(addr, &err);
    wrong += err == mapped;
    nonzero_on_error += err && v != 0;
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(nonzero_on_error, 0u);
  // Unaligned addresses and partial strobes: errors without effect.
  d.write(sh::kCrcExpected, 0x12345678);
  for (uint32_t off = 1; off < 4; ++off) {
    bool err = false;
    d.read(sh::kCrcExpected + off, &err);
    EXPECT_TRUE(err);
    EXPECT_TRUE(d.write(sh::kCrcExpected + off, 0));
  }
  for (uint32_t strb = 0; strb < 15; ++strb)
    EXPECT_TRUE(d.write(sh::kCrcExpected, 0xffffffff, strb)) << strb;
  EXPECT_TRUE(d.write(sh::kCoef, 1, 0x3));
  EXPECT_EQ(d.read(sh::kCrcExpected), 0x12345678u);
  // Back to back: n transfers take 2n clocks (setup, access; zero wait states).
  const uint64_t t0 = d.cycles();
  std::vector<std::shared_ptr<const ApbTransfer>> ts;
  for (int k = 0; k < 16; ++k)
    ts.push_back(k % 2 ? d.post(false, sh::kCoef + 4 * k)
                       : d.post(true, sh::kCoef + 4 * (k + 1), 1000 + k));
  while (!d.apb_idle()) d.tick();
  EXPECT_EQ(d.cycles() - t0, 32u);
  for (int k = 1; k < 16; k += 2) EXPECT_EQ(ts[k]->rdata, 1000u + k - 1) << k;
  // While a commit is busy (held: the output is not taken, so the samples in flight never leave):
  // shadow accesses, a second commit and CRC_EXPECTED writes are errors; the rest works.
  d.load_and_commit(paper_image());
  d.stream(cosim::paper_codes(paper_image(), 50), 0.0, 1.0, 3);
  d.ticks(400);
  const auto c = d.post(true, sh::kCtrl, d.ctrl() | sh::kCtrlCommit);
  while (!c->done) d.tick();
  EXPECT_FALSE(c->slverr);
  d.ticks(300);
  bool err = false;
  EXPECT_NE(d.read(sh::kStatus) & sh::kStatusBusy, 0u);
  EXPECT_EQ(d.read(sh::kCoef, &err), 0u);
  EXPECT_TRUE(err);
  EXPECT_TRUE(d.write(sh::kCoef, 5));
  EXPECT_TRUE(d.write(sh::kCtrl, d.ctrl() | sh::kCtrlCommit));
  EXPECT_TRUE(d.write(sh::kCrcExpected, 1));
  EXPECT_FALSE(d.write(sh::kMagLo, 3));
  EXPECT_FALSE(d.write(sh::kCtrl, d.ctrl()));
  EXPECT_EQ(d.read(sh::kMagLo), 3u);
  // Let the output go: the commit completes and the shadow is reachable again, unchanged.
  d.stream({}, 0.0, 0.0, 4);
  uint32_t st = 0;
  for (int n = 0; n < 10000 && ((st = d.read(sh::kStatus)) & sh::kStatusBusy); ++n) {
  }
  EXPECT_EQ(st & sh::kStatusBusy, 0u);
  EXPECT_NE(st & sh::kStatusDone, 0u);
  EXPECT_EQ(d.read(sh::kCoef, &err), paper_image().words[0]);
  EXPECT_FALSE(err);
  EXPECT_EQ(d.read(sh::kCrcExpected), image_crc32(paper_image()));
  d.drain();
  const ShellDriver::ApbStats& s = d.apb_stats();
  std::printf("%s: %llu APB transfers, %llu wait states\n", GetParam()->name.c_str(),
              static_cast<unsigned long long>(s.transfers),
              static_cast<unsigned long long>(s.wait_states));
  EXPECT_EQ(s.wait_states, 0u);
  EXPECT_EQ(s.stray_slverr, 0u);
  EXPECT_EQ(s.stray_prdata, 0u);
}

// Every build of the shell in the registry (rtl/configs.txt: acore_apb lines with `sim`).
INSTANTIATE_TEST_SUITE_P(Shell, Shell, ::testing::ValuesIn(rtl_builds_of(RtlTop::kShell)),
                         [](const ::testing::TestParamInfo<const RtlBuild*>& i) {
                           return i.param->name;
                         });

}  // namespace
}  // namespace acore
