#include "command.hpp"

#include <cstdlib>
#include <sstream>

namespace viewpipe::commands {

void setRun(CLI::App* command, std::function<int()> run)
{
    command->callback([run = std::move(run)] {
        if (const int code = run(); code != 0)
            throw CLI::RuntimeError(code);
    });
}

int runCommandLine(CLI::App& app, int argc, char** argv)
{
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kExitBadInput;
    }
    return 0;
}

std::pair<int, int> parseSize(const std::string& text, const std::string& option)
{
    int width = 0, height = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> width >> x >> height) || x != 'x' || !in.eof())
        throw InputError(option, "must be WxH, e.g. 1280x720 (got \"" + text + "\")");
    if (width < 1 || height < 1)
        throw InputError(option, "needs a width and a height of at least 1 pixel (got \"" + text + "\")");
    return {width, height};
}

void addPrecision(CLI::App* command, PrecisionOptions& options)
{
    command->add_option("--precision", options.precision, "float, double, long-double, float128, mpfr or exact")
        ->check(CLI::IsMember({"float", "double", "long-double", "float128", "mpfr", "exact"}))
        ->capture_default_str();
    command->add_option("--bits", options.bits, "Significand bits for --precision mpfr")->capture_default_str();
}

std::string scenesDirectory()
{
    const char* data = std::getenv("VIEWPIPE_DATA");
    return std::string(data && *data ? data : VIEWPIPE_DATA_DIR) + "/scenes";
}

std::string defaultScene()
{
    return scenesDirectory() + "/house-corner.json";
}

} // namespace viewpipe::commands
