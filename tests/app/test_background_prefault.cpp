#include "app/BackgroundPrefault.hpp"

#include <QtTest>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sys/mman.h>
#include <unistd.h>
#include <vector>

using mcpp::app::BackgroundPrefault;

namespace {

const std::size_t pageBytes = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));

// Fresh anonymous memory, unmapped when it goes out of scope; no page of it is in memory until touched.
class MappedBlock {
  public:
    explicit MappedBlock(std::size_t bytes)
        : bytes_(bytes), start_(static_cast<char*>(mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                                                        MAP_PRIVATE | MAP_ANONYMOUS, -1, 0))) {
        // Pages of the base size, so that one write makes one page resident wherever huge pages are on.
        if (start_ != MAP_FAILED)
            madvise(start_, bytes_, MADV_NOHUGEPAGE);
    }
    ~MappedBlock() {
        if (start_ != MAP_FAILED)
            munmap(start_, bytes_);
    }
    MappedBlock(const MappedBlock&) = delete;
    MappedBlock& operator=(const MappedBlock&) = delete;

    [[nodiscard]] bool valid() const { return start_ != MAP_FAILED; }
    [[nodiscard]] char* start() const { return start_; }
    [[nodiscard]] std::size_t bytes() const { return bytes_; }

    // Whether each page is in memory.
    [[nodiscard]] std::vector<bool> residentPages() const {
        std::vector<unsigned char> flags((bytes_ + pageBytes - 1) / pageBytes);
        if (mincore(start_, bytes_, flags.data()) != 0)
            return {};
        std::vector<bool> resident(flags.size());
        for (std::size_t page = 0; page < flags.size(); ++page)
            resident[page] = (flags[page] & 1U) != 0;
        return resident;
    }

  private:
    std::size_t bytes_;
    char* start_;
};

bool kernelFaultsAhead() {
#ifdef MADV_POPULATE_WRITE
    const MappedBlock probe(pageBytes);
    return probe.valid() && madvise(probe.start(), pageBytes, MADV_POPULATE_WRITE) == 0;
#else
    return false;
#endif
}

} // namespace

class TestBackgroundPrefault : public QObject {
    Q_OBJECT

  private slots:
    void init() {
        if (!kernelFaultsAhead())
            QSKIP("this kernel cannot fault pages in ahead (MADV_POPULATE_WRITE, Linux 5.14)");
    }

    void faultsInEveryPageAndKeepsWhatTheyHold() {
        const MappedBlock block(16 << 20);
        QVERIFY(block.valid());
        // Written before the helper gets there: the owner fills a block while it is faulted in.
        block.start()[0] = 17;
        block.start()[(5 << 20) + 123] = 42;
        block.start()[block.bytes() - 1] = 99;
        const std::vector<bool> before = block.residentPages();
        QCOMPARE(static_cast<int>(std::count(before.begin(), before.end(), true)), 3);

        BackgroundPrefault prefault;
        prefault.request(block.start(), block.bytes());
        prefault.waitUntilIdle();

        const std::vector<bool> after = block.residentPages();
        QCOMPARE(after.size(), block.bytes() / pageBytes);
        QCOMPARE(static_cast<std::size_t>(std::count(after.begin(), after.end(), true)), after.size());
        QCOMPARE(static_cast<int>(block.start()[0]), 17);
        QCOMPARE(static_cast<int>(block.start()[(5 << 20) + 123]), 42);
        QCOMPARE(static_cast<int>(block.start()[block.bytes() - 1]), 99);
        for (std::size_t at = 1; at < block.bytes() - 1; at += 4099)
            if (at != (5 << 20) + 123)
                QCOMPARE(static_cast<int>(block.start()[at]), 0);
    }

    void leavesPagesTheBlockSharesWithOthers() {
        // A block that starts and ends inside pages: those pages may hold other blocks.
        const MappedBlock block(64 * pageBytes);
        QVERIFY(block.valid());
        BackgroundPrefault prefault;
        prefault.request(block.start() + 100, block.bytes() - 200);
        prefault.waitUntilIdle();

        const std::vector<bool> resident = block.residentPages();
        QCOMPARE(resident.size(), std::size_t{64});
        QVERIFY(!resident.front());
        QVERIFY(!resident.back());
        QCOMPARE(static_cast<int>(std::count(resident.begin(), resident.end(), true)), 62);
    }

    void goesOnAfterABlockNoLongerMapped() {
        BackgroundPrefault prefault;
        void* gone = nullptr;
        {
            const MappedBlock freed(8 << 20);
            QVERIFY(freed.valid());
            gone = freed.start();
        }
        prefault.request(gone, 8 << 20);
        prefault.waitUntilIdle();

        const MappedBlock block(8 << 20);
        QVERIFY(block.valid());
        prefault.request(block.start(), block.bytes());
        prefault.waitUntilIdle();
        const std::vector<bool> resident = block.residentPages();
        QCOMPARE(static_cast<std::size_t>(std::count(resident.begin(), resident.end(), true)),
                 resident.size());
    }
};

QTEST_GUILESS_MAIN(TestBackgroundPrefault)
#include "test_background_prefault.moc"
