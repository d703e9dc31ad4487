#pragma once

#include "clicommand.h"
#include "core/protocol/addressrange.h"

#include <functional>
#include <map>
#include <vector>

namespace Fatek {

struct CliStepArgs;

// read ADDR[:FORMAT] [COUNT] (consecutive elements, 44/46, in as many requests as it takes),
// read ADDR ADDR... (a mixed list, 48). Its parser also takes forced's arguments.
class CliReadCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);

protected:
    void run() override;

private:
    using ReadWords = std::map<Address, std::uint32_t>;
    // Reads the element runs from `done` elements into the first one on, then calls `finished`.
    void readRuns(std::vector<AddressRange> runs, std::size_t done, ReadWords words,
                  std::function<void(const ReadWords &)> finished);
    void printElements(const std::vector<std::uint32_t> &values);
    void printItems(const ReadWords &words);
};

} // namespace Fatek
