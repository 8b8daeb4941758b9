#include "render/PreparedPictureMemory.hpp"

#include <QtTest>
#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace mcpp;

class TestPreparedPictureMemory : public QObject {
    Q_OBJECT

  private slots:
    void nothingOnOfferGivesNothing() { QVERIFY(render::PreparedPictureMemory::take(1024) == nullptr); }

    // The block is whole huge pages, aligned to one, taken once, and only by a picture that fits in it.
    void takenOnceWhenItFits() {
        constexpr std::size_t megabyte = std::size_t{1} << 20;
        const render::PreparedPictureMemory prepared(3 * megabyte);
        QVERIFY(render::PreparedPictureMemory::take(4 * megabyte + 1) == nullptr);
        void* block = render::PreparedPictureMemory::take(4 * megabyte); // 3 MB rounded up to two 2 MB pages
        QVERIFY(block != nullptr);
        QCOMPARE(reinterpret_cast<std::uintptr_t>(block) % render::PreparedPictureMemory::hugePage,
                 std::uintptr_t{0});
        std::memset(block, 0x5a, 4 * megabyte); // all of it is the caller's
        QVERIFY(render::PreparedPictureMemory::take(megabyte) == nullptr);
        std::free(block);
    }

    // A second block made while one is on offer is not offered; the first stays the one to take.
    void oneOfferAtATime() {
        constexpr std::size_t megabyte = std::size_t{1} << 20;
        const render::PreparedPictureMemory first(2 * megabyte);
        {
            const render::PreparedPictureMemory second(8 * megabyte);
            QVERIFY(render::PreparedPictureMemory::take(4 * megabyte) == nullptr);
        }
        void* block = render::PreparedPictureMemory::take(2 * megabyte);
        QVERIFY(block != nullptr);
        std::free(block);
    }

    // Once the block's owner is gone, nothing is offered.
    void nothingAfterTheOwnerIsGone() {
        { const render::PreparedPictureMemory prepared(std::size_t{2} << 20); }
        QVERIFY(render::PreparedPictureMemory::take(1024) == nullptr);
    }
};

QTEST_APPLESS_MAIN(TestPreparedPictureMemory)
#include "test_prepared_picture_memory.moc"
