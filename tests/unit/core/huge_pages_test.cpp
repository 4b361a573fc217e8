// The huge-page advice: which part of a buffer the kernel is asked to back with huge pages, seen
// in the kernel's own account of the mapping (/proc/self/smaps, flag "hg").

#include "core/huge_pages.hpp"

#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <utility>

namespace strata {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;

/// Whether the mapping that holds `address` carries the huge-page advice.
bool advised(std::uintptr_t address) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0;
    std::uintptr_t end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-' &&
        line.find(' ') != std::string::npos && line.find(':') > line.find(' ')) {
      inside = begin <= address && address < end;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line.find(" hg") != std::string::npos;
  }
  return false;
}

/// An anonymous mapping of its own, so that the advice cannot reach anything else.
class Mapping {
 public:
  explicit Mapping(std::size_t bytes) : bytes_(bytes) {
    data_ = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  }
  ~Mapping() {
    if (data_ != MAP_FAILED) munmap(data_, bytes_);
  }
  Mapping(const Mapping&) = delete;
  Mapping& operator=(const Mapping&) = delete;
  std::uintptr_t address() const { return reinterpret_cast<std::uintptr_t>(data_); }
  bool ok() const { return data_ != MAP_FAILED; }

 private:
  void* data_ = MAP_FAILED;
  std::size_t bytes_ = 0;
};

bool kernel_offers_huge_pages() {
  return std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled");
}

constexpr std::uintptr_t kOwnMapping = std::uintptr_t{32} << 20;

TEST(AdviseHugePages, AdvisesTheWholeHugePagesInsideALargeBufferAndNothingAround) {
  if (!kernel_offers_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  Mapping mapping(kOwnMapping + 4 * kHugePage);
  ASSERT_TRUE(mapping.ok());
  // A buffer starting just past a huge-page boundary: the advice starts at the next boundary.
  const std::uintptr_t first = (mapping.address() + kHugePage) & ~(kHugePage - 1);
  const std::uintptr_t buffer = first - 4096;
  const std::uintptr_t whole = kOwnMapping + kHugePage;  // the whole huge pages inside
  advise_huge_pages(reinterpret_cast<void*>(buffer), whole + 8192);
  EXPECT_TRUE(advised(first));
  EXPECT_TRUE(advised(first + whole - 1));
  EXPECT_FALSE(advised(buffer));         // the partial page before
  EXPECT_FALSE(advised(first + whole));  // the partial page after
}

TEST(AdviseHugePages, LeavesBuffersThatMayShareTheHeapAlone) {
  if (!kernel_offers_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  Mapping mapping(kOwnMapping + 2 * kHugePage);
  ASSERT_TRUE(mapping.ok());
  const std::uintptr_t first = (mapping.address() + kHugePage) & ~(kHugePage - 1);
  // 32 MiB exactly, from a huge-page boundary: sixteen whole huge pages, but not surely a
  // mapping of its own.
  advise_huge_pages(reinterpret_cast<void*>(first), kOwnMapping);
  EXPECT_FALSE(advised(first));
  EXPECT_FALSE(advised(first + kOwnMapping - 1));
  advise_huge_pages(nullptr, 2 * kOwnMapping);  // nothing to advise
}

TEST(ReserveHugePages, ReservesAnEmptyVectorOnAdvisedPages) {
  if (!kernel_offers_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  std::vector<double> values;
  reserve_huge_pages(values, 5 << 20);  // 40 MiB
  EXPECT_TRUE(values.empty());
  EXPECT_GE(values.capacity(), std::size_t{5} << 20);
  const auto data = reinterpret_cast<std::uintptr_t>(values.data());
  EXPECT_TRUE(advised((data + kHugePage) & ~(kHugePage - 1)));
}

struct Slot {
  std::uint32_t tag;
  std::uint32_t value;
};

TEST(ZeroedPageArray, HoldsZeroedItemsWhereverItsMemoryComesFrom) {
  // Under a huge page (from the heap) and above it (a mapping of its own).
  for (const std::size_t n : {std::size_t{1}, std::size_t{1000}, (kHugePage / sizeof(Slot)) + 1}) {
    SCOPED_TRACE(n);
    ZeroedPageArray<Slot> slots(n);
    ASSERT_EQ(slots.size(), n);
    for (std::size_t i = 0; i < n; i += 97) ASSERT_EQ(slots[i].tag | slots[i].value, 0U);
    ASSERT_EQ(slots[n - 1].tag | slots[n - 1].value, 0U);
    slots[n - 1] = Slot{1, 2};
    // Moved, the array keeps its items and the one it leaves holds none.
    ZeroedPageArray<Slot> moved(std::move(slots));
    EXPECT_EQ(slots.size(), 0U);
    EXPECT_EQ(moved[n - 1].value, 2U);
    ZeroedPageArray<Slot> other(3);
    other = std::move(moved);
    EXPECT_EQ(other.size(), n);
    EXPECT_EQ(other[n - 1].tag, 1U);
  }
  const ZeroedPageArray<Slot> none;
  EXPECT_EQ(none.size(), 0U);
  const ZeroedPageArray<Slot> empty(0);
  EXPECT_EQ(empty.size(), 0U);
}

TEST(ZeroedPageArray, ALargeArrayIsAMappingOfItsOwnAdvisedToHugePages) {
  if (!kernel_offers_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  const ZeroedPageArray<Slot> slots(4 * kHugePage / sizeof(Slot));
  EXPECT_TRUE(advised(reinterpret_cast<std::uintptr_t>(&slots[0])));
}

TEST(ZeroedPageArray, MoreMemoryThanTheSystemGivesIsBadAlloc) {
  EXPECT_THROW(ZeroedPageArray<Slot>(std::size_t{1} << 58), std::bad_alloc);
}

}  // namespace
}  // namespace strata
