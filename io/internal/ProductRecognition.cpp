#include "io/internal/ProductRecognition.hpp"

#include "io/internal/ClassTablePresets.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>

namespace mcpp::io::internal {

namespace {

constexpr double kCoveredPixelShare = 0.99; // a few pixels of stray codes do not hide a product
constexpr double kMatchingShare = 0.6;      // names or colours of at least this share of the classes
constexpr double kSpecificityMargin = 2.0;  // a preset fitting this much more tightly wins a tie on codes
constexpr int kColourTolerance = 8;         // per channel: palettes are rounded differently

// Letters and digits only, lower case: "Developed, Open Space" and "developed open space" are one name.
std::string nameKey(const std::string& name) {
    std::string key;
    for (const unsigned char character : name)
        if (std::isalnum(character))
            key += static_cast<char>(std::tolower(character));
    return key;
}

// A word or phrase not inside a longer word: "clc" in "clc_2018" and "corine2006", not in "clcx".
bool mentions(const std::string& lowerText, const std::string& word) {
    for (std::size_t at = lowerText.find(word); at != std::string::npos; at = lowerText.find(word, at + 1)) {
        const bool startsWord = at == 0 || !std::isalpha(static_cast<unsigned char>(lowerText[at - 1]));
        const std::size_t end = at + word.size();
        const bool endsWord =
            end == lowerText.size() || !std::isalpha(static_cast<unsigned char>(lowerText[end]));
        if (startsWord && endsWord)
            return true;
    }
    return false;
}

bool mentionsAny(const std::string& lowerText, const std::vector<std::string>& words) {
    return std::any_of(words.begin(), words.end(),
                       [&](const std::string& word) { return mentions(lowerText, word); });
}

struct Candidate {
    const PresetDefinition* preset = nullptr;
    double specificity = 0.0; // share of the preset's classes the raster holds
};

std::vector<Candidate> coveringPresets(const LoadedRaster& raster) {
    std::int64_t total = 0;
    for (const auto& [value, count] : raster.classPixelCounts)
        total += count;
    std::vector<Candidate> candidates;
    if (total == 0)
        return candidates;
    for (const PresetDefinition& preset : presetDefinitions()) {
        std::int64_t covered = 0;
        std::size_t known = 0;
        for (const auto& [value, count] : raster.classPixelCounts) {
            const bool hasRow =
                std::any_of(preset.classes.begin(), preset.classes.end(),
                            [value = value](const LandCoverClass& row) { return row.value == value; });
            if (hasRow) {
                covered += count;
                ++known;
            }
        }
        if (static_cast<double>(covered) >= kCoveredPixelShare * static_cast<double>(total))
            candidates.push_back(
                {&preset, static_cast<double>(known) / static_cast<double>(preset.classes.size())});
    }
    return candidates;
}

const LegendEntry* legendEntryOf(const LoadedRaster& raster, std::int32_t value) {
    const auto found = std::find_if(raster.legend.begin(), raster.legend.end(),
                                    [value](const LegendEntry& entry) { return entry.value == value; });
    return found == raster.legend.end() ? nullptr : &*found;
}

bool closeColours(std::uint32_t first, std::uint32_t second) {
    for (const unsigned shift : {16U, 8U, 0U}) {
        const int a = static_cast<int>((first >> shift) & 0xffU);
        const int b = static_cast<int>((second >> shift) & 0xffU);
        if (std::abs(a - b) > kColourTolerance)
            return false;
    }
    return true;
}

// Share of the raster's classes whose legend entry agrees with the preset's row, among those with an
// entry of that kind; 0 when fewer than half the classes have one.
double agreement(const LoadedRaster& raster, const PresetDefinition& preset,
                 const std::function<bool(const LegendEntry&)>& hasIt,
                 const std::function<bool(const LegendEntry&, const LandCoverClass&)>& agrees) {
    std::size_t described = 0;
    std::size_t agreeing = 0;
    for (const auto& [value, count] : raster.classPixelCounts) {
        const LegendEntry* entry = legendEntryOf(raster, value);
        if (entry == nullptr || !hasIt(*entry))
            continue;
        ++described;
        const auto row =
            std::find_if(preset.classes.begin(), preset.classes.end(),
                         [value = value](const LandCoverClass& item) { return item.value == value; });
        if (row != preset.classes.end() && agrees(*entry, *row))
            ++agreeing;
    }
    if (described == 0 || 2 * described < raster.classPixelCounts.size())
        return 0.0;
    return static_cast<double>(agreeing) / static_cast<double>(described);
}

double nameAgreement(const LoadedRaster& raster, const PresetDefinition& preset) {
    return agreement(
        raster, preset, [](const LegendEntry& entry) { return !nameKey(entry.name).empty(); },
        [](const LegendEntry& entry, const LandCoverClass& row) {
            return nameKey(entry.name) == nameKey(row.name);
        });
}

double colourAgreement(const LoadedRaster& raster, const PresetDefinition& preset) {
    return agreement(
        raster, preset, [](const LegendEntry& entry) { return entry.colorRgb.has_value(); },
        [](const LegendEntry& entry, const LandCoverClass& row) {
            return closeColours(*entry.colorRgb, row.colorRgb);
        });
}

bool hasNames(const LoadedRaster& raster) {
    std::size_t named = 0;
    for (const auto& [value, count] : raster.classPixelCounts)
        if (const LegendEntry* entry = legendEntryOf(raster, value); entry != nullptr && !entry->name.empty())
            ++named;
    return named > 0 && 2 * named >= raster.classPixelCounts.size();
}

// The candidate passing the test, the one fitting most tightly when several do and it clearly does.
const Candidate* chosen(const std::vector<Candidate>& candidates,
                        const std::function<bool(const Candidate&)>& passes) {
    std::vector<const Candidate*> passing;
    for (const Candidate& candidate : candidates)
        if (passes(candidate))
            passing.push_back(&candidate);
    if (passing.empty())
        return nullptr;
    std::sort(passing.begin(), passing.end(),
              [](const Candidate* a, const Candidate* b) { return a->specificity > b->specificity; });
    if (passing.size() > 1 && passing[0]->specificity < kSpecificityMargin * passing[1]->specificity)
        return nullptr;
    return passing.front();
}

ProductMatch matchOf(const Candidate& candidate, std::string evidence) {
    return {candidate.preset->name, candidate.preset->productName, std::move(evidence)};
}

} // namespace

std::optional<ProductMatch> recogniseProduct(const LoadedRaster& raster) {
    const std::vector<Candidate> candidates = coveringPresets(raster);
    if (candidates.empty())
        return std::nullopt;
    const std::string metadata = lowercase(raster.metadataText);
    if (const Candidate* found = chosen(candidates, [&](const Candidate& candidate) {
            return mentionsAny(metadata, candidate.preset->productWords);
        }))
        return matchOf(*found, "its metadata");
    const std::string fileName = lowercase(std::filesystem::path(raster.path).filename().string());
    if (const Candidate* found = chosen(candidates, [&](const Candidate& candidate) {
            return mentionsAny(fileName, candidate.preset->productWords);
        }))
        return matchOf(*found, "its file name");
    if (hasNames(raster)) {
        // The file names its classes: a product is recognised only by those names.
        if (const Candidate* found = chosen(candidates, [&](const Candidate& candidate) {
                return nameAgreement(raster, *candidate.preset) >= kMatchingShare;
            }))
            return matchOf(*found, "its class names");
        return std::nullopt;
    }
    if (const Candidate* found = chosen(candidates, [&](const Candidate& candidate) {
            return colourAgreement(raster, *candidate.preset) >= kMatchingShare;
        }))
        return matchOf(*found, "its palette");
    const std::string crs = lowercase(raster.sourceCrsName);
    constexpr std::size_t kFewestCodes = 3; // one or two codes fit too many schemes
    if (raster.classPixelCounts.size() < kFewestCodes)
        return std::nullopt;
    if (const Candidate* found = chosen(candidates, [&](const Candidate& candidate) {
            return candidate.preset->codeEvidence == CodeEvidence::Alone;
        }))
        return matchOf(*found, "its codes");
    if (const Candidate* found = chosen(candidates, [&](const Candidate& candidate) {
            return candidate.preset->codeEvidence == CodeEvidence::WithCrs &&
                   mentionsAny(crs, candidate.preset->crsWords);
        }))
        return matchOf(*found, "its codes and its CRS (" + raster.sourceCrsName + ")");
    return std::nullopt;
}

} // namespace mcpp::io::internal
