// The exported web page in a real browser: Debian's Chromium, headless, with
// WebGL through SwiftShader, driven over the DevTools protocol on a pipe
// (--remote-debugging-pipe: messages are JSON ended by a NUL byte). The page
// is stepped with key presses only; each stage's picture is compared with
// the app's export of the same stage, and the console must stay free of errors.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <QByteArray>
#include <QImage>
#include <QProcess>
#include <QStringList>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "build_paths.h"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/lesson.hpp"
#include "viewpipe/report/world_view.hpp"
#include "viewpipe/scene.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kData = viewpipe::build::dataDir;
constexpr int kWidth = 960, kHeight = 540; // the export's picture and the browser's window

struct Finished {
    int exitCode;
    std::string output;
};

Finished viewpipe(const QStringList& arguments)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(viewpipe::build::viewpipeExe, arguments);
    const bool finished = process.waitForFinished(600000);
    const bool ran = finished && process.error() == QProcess::UnknownError && process.exitStatus() == QProcess::NormalExit;
    return {ran ? process.exitCode() : -1, process.readAll().toStdString() + (ran ? "" : "\n(did not run to its end: " +
                                                                               process.errorString().toStdString() + ")")};
}

// A headless Chromium and one page in it, its window `width` by `height`.
class Browser {
public:
    explicit Browser(const fs::path& profile, int width = kWidth, int height = kHeight)
    {
        int toBrowser[2], fromBrowser[2];
        if (::pipe(toBrowser) != 0 || ::pipe(fromBrowser) != 0)
            throw std::runtime_error("pipe failed");
        // Out of the way of 3 and 4, where Chromium expects them.
        const int read = ::fcntl(toBrowser[0], F_DUPFD_CLOEXEC, 10), write = ::fcntl(fromBrowser[1], F_DUPFD_CLOEXEC, 10);
        ::close(toBrowser[0]);
        ::close(fromBrowser[1]);
        in_ = fromBrowser[0];
        out_ = toBrowser[1];
        ::fcntl(in_, F_SETFD, FD_CLOEXEC);
        ::fcntl(out_, F_SETFD, FD_CLOEXEC);
        if (read < 0 || write < 0) {
            closeAll({read, write});
            throw std::runtime_error("cannot move the pipes out of the way");
        }
        posix_spawnattr_t attributes; // its own process group: the renderers end with it
        posix_spawnattr_init(&attributes);
        posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
        posix_spawnattr_setpgroup(&attributes, 0);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, read, 3);
        posix_spawn_file_actions_adddup2(&actions, write, 4);
        // Its own messages (D-Bus, fonts) go to a log beside the profile.
        posix_spawn_file_actions_addopen(&actions, 2, (profile.string() + ".log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        std::vector<std::string> arguments = {
            "chromium", "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
            "--remote-debugging-pipe", "--hide-scrollbars", "--mute-audio", "--no-first-run",
            "--user-data-dir=" + profile.string(), "--window-size=" + std::to_string(width) + "," + std::to_string(height),
            "about:blank"};
        std::vector<char*> argv;
        for (std::string& a : arguments)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        const int status = ::posix_spawnp(&pid_, "chromium", &actions, &attributes, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attributes);
        closeAll({read, write});
        if (status != 0) {
            closeAll({in_, out_});
            throw std::runtime_error("cannot start chromium (Debian package chromium)");
        }
        try {
            const json targets = call("Target.getTargets");
            for (const json& t : targets["targetInfos"])
                if (t["type"] == "page")
                    session_ = call("Target.attachToTarget", {{"targetId", t["targetId"]}, {"flatten", true}})["sessionId"];
            if (session_.empty())
                throw std::runtime_error("chromium has no page");
            for (const char* domain : {"Runtime.enable", "Log.enable", "Page.enable", "Network.enable"})
                call(domain, json::object(), session_);
            call("Emulation.setDeviceMetricsOverride",
                 {{"width", width}, {"height", height}, {"deviceScaleFactor", 1}, {"mobile", false}}, session_);
        } catch (...) {
            stop();
            throw;
        }
    }
    ~Browser() { stop(); }

    json call(const std::string& method, const json& params = json::object(), const std::string& session = "")
    {
        const int id = send(method, params, session);
        while (true) {
            json message = receive();
            if (message.contains("id") && message["id"] == id) {
                if (message.contains("error"))
                    throw std::runtime_error(method + ": " + message["error"].dump());
                return message["result"];
            }
            events.push_back(std::move(message));
        }
    }
    json page(const std::string& method, const json& params = json::object()) { return call(method, params, session_); }

    json evaluate(const std::string& expression)
    {
        return page("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}})["result"].value("value", json());
    }
    // Waits until the expression is true; false after `seconds`.
    bool waitFor(const std::string& expression, double seconds = 30)
    {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (evaluate(expression) == json(true))
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }
    // Opens `url` and waits until the page has drawn and its core has loaded; false after 30 s.
    bool openWithCore(const std::string& url)
    {
        page("Page.navigate", {{"url", url}});
        return waitFor("document.body.dataset.ready === '1' && document.body.dataset.core === '1'");
    }
    // `modifiers`: DevTools' bits (8: Shift).
    void press(const std::string& key, int keyCode, int modifiers = 0)
    {
        // Enter types a character too: that is what submits a form.
        const bool enter = key == "Enter";
        for (const char* type : {enter ? "keyDown" : "rawKeyDown", "keyUp"}) {
            json event = {{"type", type}, {"key", key}, {"code", key}, {"windowsVirtualKeyCode", keyCode}, {"modifiers", modifiers}};
            if (enter && std::string(type) == "keyDown")
                event["text"] = "\r";
            page("Input.dispatchKeyEvent", event);
        }
    }
    QImage screenshot()
    {
        const std::string png = page("Page.captureScreenshot", {{"format", "png"}})["data"];
        return QImage::fromData(QByteArray::fromBase64(QByteArray::fromStdString(png)), "PNG");
    }

    // What went wrong in the page: exceptions, console errors, requests that left the file.
    std::vector<std::string> problems() const
    {
        std::vector<std::string> found;
        for (const json& e : events) {
            const std::string method = e.value("method", "");
            const json& p = e.contains("params") ? e["params"] : json();
            if (method == "Runtime.exceptionThrown")
                found.push_back("exception: " + p["exceptionDetails"].dump());
            else if (method == "Runtime.consoleAPICalled" && p["type"] == "error")
                found.push_back("console.error: " + p["args"].dump());
            else if (method == "Log.entryAdded" && p["entry"]["level"] == "error")
                found.push_back("log: " + p["entry"]["text"].get<std::string>());
            else if (method == "Network.requestWillBeSent") {
                const std::string url = p["request"]["url"];
                if (url.rfind("file:", 0) != 0 && url.rfind("data:", 0) != 0 && url != "about:blank")
                    found.push_back("network request: " + url);
            }
        }
        return found;
    }

    std::vector<json> events;

private:
    static void closeAll(std::initializer_list<int> fds)
    {
        for (int fd : fds)
            if (fd >= 0)
                ::close(fd);
    }
    // Asks the browser to close, then ends its whole process group; reaps it once.
    void stop()
    {
        try {
            send("Browser.close", json::object(), "");
        } catch (...) {
        }
        bool reaped = false;
        for (int k = 0; k < 50 && !reaped; ++k) {
            reaped = ::waitpid(pid_, nullptr, WNOHANG) == pid_;
            if (!reaped)
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        ::kill(-pid_, SIGKILL); // the group: renderers and the GPU process too
        if (!reaped)
            ::waitpid(pid_, nullptr, 0);
        closeAll({in_, out_});
    }

    int send(const std::string& method, const json& params, const std::string& session)
    {
        json message = {{"id", ++id_}, {"method", method}, {"params", params}};
        if (!session.empty())
            message["sessionId"] = session;
        const std::string text = message.dump() + '\0';
        for (std::size_t done = 0; done < text.size();) {
            const ssize_t n = ::write(out_, text.data() + done, text.size() - done);
            if (n <= 0)
                throw std::runtime_error("chromium's pipe closed");
            done += std::size_t(n);
        }
        return id_;
    }
    json receive()
    {
        while (true) {
            const std::size_t end = buffer_.find('\0');
            if (end != std::string::npos) {
                json message = json::parse(buffer_.substr(0, end));
                buffer_.erase(0, end + 1);
                return message;
            }
            pollfd p{in_, POLLIN, 0};
            if (::poll(&p, 1, 60000) <= 0)
                throw std::runtime_error("chromium did not answer within a minute");
            char chunk[65536];
            const ssize_t n = ::read(in_, chunk, sizeof chunk);
            if (n <= 0)
                throw std::runtime_error("chromium ended");
            buffer_.append(chunk, std::size_t(n));
        }
    }

    pid_t pid_ = -1;
    int in_ = -1, out_ = -1, id_ = 0;
    std::string session_, buffer_;
};

// Waits until the browser has saved a download as `file` (its partial file renamed); false after `seconds`.
bool waitForFile(const fs::path& file, double seconds = 30)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (fs::exists(file))
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

// A click where the page draws a world point ("[x, y, z]", or "[x, y, z], K" in the storyboard's cell of stage K).
::testing::AssertionResult clickOn(Browser& browser, const std::string& point)
{
    const json at = browser.evaluate("JSON.stringify(window.viewpipe.pixelOf(" + point + "))");
    if (!at.is_string())
        return ::testing::AssertionFailure() << point << " is not drawn: " << at;
    const json pixel = json::parse(at.get<std::string>());
    for (const char* type : {"mousePressed", "mouseReleased"})
        browser.page("Input.dispatchMouseEvent", {{"type", type}, {"x", pixel["x"]}, {"y", pixel["y"]},
                                                  {"button", "left"}, {"clickCount", 1}});
    return ::testing::AssertionSuccess();
}

// Pixels that are not the (white) background.
std::vector<bool> drawn(const QImage& image)
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    std::vector<bool> mask(std::size_t(rgb.width() * rgb.height()));
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) {
            const QRgb c = rgb.pixel(x, y);
            mask[std::size_t(y * rgb.width() + x)] = std::min({qRed(c), qGreen(c), qBlue(c)}) < 215;
        }
    return mask;
}

// The share of `a`'s drawn pixels with a drawn pixel of `b` within `reach` pixels.
double coveredShare(const std::vector<bool>& a, const std::vector<bool>& b, int width, int height, int reach)
{
    long total = 0, covered = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!a[std::size_t(y * width + x)])
                continue;
            ++total;
            bool near = false;
            for (int dy = -reach; dy <= reach && !near; ++dy)
                for (int dx = -reach; dx <= reach && !near; ++dx) {
                    const int u = x + dx, v = y + dy;
                    near = u >= 0 && v >= 0 && u < width && v < height && b[std::size_t(v * width + u)];
                }
            covered += near;
        }
    return total ? double(covered) / double(total) : 0;
}

class WebPage : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dir_ = new fs::path(fs::temp_directory_path() / ("viewpipe-web-" + std::to_string(::getpid())));
        fs::remove_all(*dir_);
        const Finished run = viewpipe({"export", QString::fromStdString(kData + "/scenes/house.json"), "--out",
                                  QString::fromStdString((*dir_ / "house").string()), "--format", "html,png", "--size",
                                  QString("%1x%2").arg(kWidth).arg(kHeight), "--quiet"});
        ASSERT_EQ(run.exitCode, 0) << run.output;
    }
    static void TearDownTestSuite()
    {
        fs::remove_all(*dir_);
        delete dir_;
    }
    static fs::path* dir_;
};
fs::path* WebPage::dir_ = nullptr;

TEST_F(WebPage, IsOneFileThatAsksTheNetworkForNothing)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    ASSERT_TRUE(fs::exists(page));
    std::cout << "the house's page: " << fs::file_size(page) << " bytes\n";
    EXPECT_LE(fs::file_size(page), 4u << 20) << "the house's page, with the core as WebAssembly, must stay under 4 MB";
    std::ifstream in(page);
    std::stringstream text;
    text << in.rdbuf();
    // Everything inline: no script, style sheet or font fetched (the browser test watches the network too).
    for (const char* outside : {"<script src", "<link", "url(http", "url(fonts/"})
        EXPECT_EQ(text.str().find(outside), std::string::npos) << outside;
}

TEST_F(WebPage, StepsWithKeysAndDrawsEachStageAsTheAppDoes)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile");
    browser.page("Page.navigate", {{"url", "file://" + page.string() + "#figure"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1'")) << "the page never got ready";
    const int stages = browser.evaluate("document.querySelectorAll('#stage-list li').length").get<int>();
    ASSERT_EQ(stages, 6); // the world and Foley's five stages
    const std::vector<std::string> names = {"00-world", "01-t-vrp", "02-r", "03-t-prp", "04-sh-per", "05-s-per"};
    std::vector<std::vector<bool>> app, shown;
    for (int k = 0; k < stages; ++k) {
        if (k > 0)
            browser.press("ArrowRight", 39);
        ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '" + std::to_string(k) +
                                    "' && !document.body.dataset.moving"))
            << "stage " << k << " not reached";
        const std::string live = browser.evaluate("document.getElementById('live').textContent");
        EXPECT_NE(live.find("Stage " + std::to_string(k) + " of 5"), std::string::npos) << live;
        const QImage shot = browser.screenshot();
        ASSERT_EQ(shot.size(), QSize(kWidth, kHeight));
        shot.save(QString::fromStdString((*dir_ / ("page-" + names[std::size_t(k)] + ".png")).string()));
        const QImage picture(QString::fromStdString((*dir_ / "house" / (names[std::size_t(k)] + ".png")).string()));
        ASSERT_EQ(picture.size(), shot.size());
        app.push_back(drawn(picture));
        shown.push_back(drawn(shot));
    }
    // Each stage's page picture matches the app's picture of that stage, as
    // well as any other (stages framed together look much alike: T(-VRP) is
    // the identity here), and the measure tells pictures apart (the subject
    // fills much of each, so two stages share two thirds of their ink).
    for (int k = 0; k < stages; ++k) {
        std::vector<double> share;
        for (int j = 0; j < stages; ++j)
            share.push_back(std::min(coveredShare(app[std::size_t(j)], shown[std::size_t(k)], kWidth, kHeight, 3),
                                     coveredShare(shown[std::size_t(k)], app[std::size_t(j)], kWidth, kHeight, 3)));
        std::cout << "page stage " << k << " against the app's stages:";
        for (double x : share)
            std::cout << " " << x;
        std::cout << "\n";
        EXPECT_GE(share[std::size_t(k)], 0.8) << "stage " << k;
        EXPECT_GE(share[std::size_t(k)], *std::max_element(share.begin(), share.end()) - 0.02) << "stage " << k;
        EXPECT_LT(*std::min_element(share.begin(), share.end()), 0.7) << "stage " << k;
    }
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// A value typed into the Scene panel's field (its aria-label), and Enter.
void typeInto(Browser& browser, const std::string& field, const std::string& text);

TEST_F(WebPage, LinksToAMomentTracesAVertexAndTypesetsTheMatrices)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-links");
    browser.page("Page.navigate", {{"url", "file://" + page.string() + "#stage=4&yaw=20"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1'"));
    EXPECT_EQ(browser.evaluate("document.body.dataset.stage"), "4");
    // The panels scroll, not the page: KaTeX's hidden MathML stays inside them (it stretched the page to
    // twice the window). At this small window the world view's least height may add a few pixels.
    EXPECT_LT(browser.evaluate("document.documentElement.scrollHeight - innerHeight").get<int>(), 10);
    // The stage list's symbols typeset by KaTeX from the core's math.
    EXPECT_EQ(browser.evaluate("document.querySelector('[aria-current=step]').textContent.startsWith('4. ')"), true);
    EXPECT_EQ(browser.evaluate("document.querySelector('[aria-current=step] annotation').textContent"),
              "\\mathit{SH}_{\\mathrm{per}}");
    // KaTeX typeset the stage's matrix and the product so far.
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('#matrix .katex, #cumulative .katex').length"), 2);
    EXPECT_NE(browser.evaluate("document.getElementById('matrix').textContent").get<std::string>().find("SH"),
              std::string::npos);

    // The clicker's and the keyboard's keys; the fragment follows.
    browser.press("PageDown", 34);
    ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '5' && !document.body.dataset.moving"));
    EXPECT_NE(browser.evaluate("location.hash").get<std::string>().find("stage=5"), std::string::npos);
    browser.press("Home", 36);
    ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '0'"));
    browser.press("End", 35);
    ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '5'"));
    browser.press("PageUp", 33);
    ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '4' && !document.body.dataset.moving"));

    // Labels placed by the core in the page: for the view at rest, those of the stage at rest (as the core
    // placed them in the page, with the page's fonts: a value typed anew has it evaluate the scene); turned,
    // placed anew around the same caption and legend, none over another, all inside the picture.
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'"));
    typeInto(browser, "view.prp[0]", "8.0");
    browser.evaluate("document.activeElement.blur()");
    ASSERT_TRUE(browser.waitFor("!document.getElementById('undo').disabled"));
    browser.press("0", 48); // the view as at rest (the link turned it by 20 degrees)
    const auto boxes = [](const json& labels) {
        std::vector<std::pair<std::string, std::array<double, 4>>> out;
        for (const json& l : labels)
            out.push_back({l["text"], {l["box"][0], l["box"][1], l["box"][2], l["box"][3]}});
        return out;
    };
    const auto rest = boxes(json::parse(browser.evaluate("JSON.stringify(window.viewpipe.restLabels())").get<std::string>()));
    const auto same = boxes(json::parse(browser.evaluate("JSON.stringify(window.viewpipe.turnedLabels())").get<std::string>()));
    ASSERT_EQ(same.size(), rest.size());
    for (std::size_t k = 0; k < rest.size(); ++k) {
        EXPECT_EQ(same[k].first, rest[k].first);
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(same[k].second[c], rest[k].second[c], 1e-6) << rest[k].first;
    }
    for (int turn = 0; turn < 3; ++turn)
        browser.press("ArrowRight", 39, 8); // Shift: orbit
    const auto turned = boxes(json::parse(browser.evaluate("JSON.stringify(window.viewpipe.turnedLabels())").get<std::string>()));
    ASSERT_FALSE(turned.empty());
    EXPECT_NE(turned, rest) << "turned 30 degrees, the labels move";
    for (std::size_t a = 0; a < turned.size(); ++a) {
        const auto& [x0, y0, x1, y1] = turned[a].second;
        EXPECT_TRUE(x0 >= 0 && y0 >= 0 && x1 <= kWidth && y1 <= kHeight) << turned[a].first;
        for (std::size_t b = a + 1; b < turned.size(); ++b) {
            const auto& o = turned[b].second;
            EXPECT_FALSE(x0 < o[2] && o[0] < x1 && y0 < o[3] && o[1] < y1) << turned[a].first << " over " << turned[b].first;
        }
    }
    browser.press("0", 48); // the view back

    // A click on a vertex traces it: a corner of the house's front, clicked where the page draws it.
    ASSERT_TRUE(clickOn(browser, "[0, 0, 54]"));
    ASSERT_TRUE(browser.waitFor("document.querySelectorAll('#trace tr').length === 7"));
    // After T(-PRP), the PRP being (8, 6, 84) in VRC = world here, the corner is at (-8, -6, -30).
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('#trace tr')[4].cells[0].querySelector('annotation').textContent"),
              "T(-\\mathit{PRP})");
    // The coordinates as the core writes them for the app's Matrices panel (exact here: typeset math).
    EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('#trace tr')[4].cells].slice(1)"
                               ".map(c => c.querySelector('annotation').textContent).join(' ')"),
              "-8 -6 -30 1");
    EXPECT_EQ(browser.evaluate("document.querySelector('#trace p').textContent.slice(0, 19)"), "After the divide: (");

    // A link turned past the view's limits is held to them, as a lesson file and the app hold it: pitch to
    // ±89 degrees, zoom to 0.1–20; and the keys stop there.
    browser.page("Page.navigate", {{"url", "about:blank"}}); // a page loaded anew, not a fragment changed
    browser.page("Page.navigate", {{"url", "file://" + page.string() + "#stage=2&pitch=120&zoom=50"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1'"));
    EXPECT_EQ(browser.evaluate("location.hash"), "#stage=2&pitch=89.0&zoom=20.000");
    browser.press("+", 187);
    browser.press("ArrowDown", 40, 8); // Shift: orbit 10 degrees down
    EXPECT_EQ(browser.evaluate("location.hash"), "#stage=2&pitch=89.0&zoom=20.000");
    browser.page("Page.navigate", {{"url", "about:blank"}});
    browser.page("Page.navigate", {{"url", "file://" + page.string() + "#stage=2&pitch=-120&zoom=0.01"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1'"));
    EXPECT_EQ(browser.evaluate("location.hash"), "#stage=2&pitch=-89.0&zoom=0.100");
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

TEST_F(WebPage, ComputesTheSceneWithTheCoreAsTheCliDoes)
{
    const Finished cli = viewpipe({"pipeline", QString::fromStdString(kData + "/scenes/house.json"), "--json"});
    ASSERT_EQ(cli.exitCode, 0) << cli.output;
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-core");
    browser.page("Page.navigate", {{"url", "file://" + page.string()}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'")) << "the core never loaded";
    // The JSON view holds what `viewpipe pipeline house.json --json` prints, computed in the page.
    EXPECT_EQ(browser.evaluate("document.getElementById('pipeline-json').textContent").get<std::string>() + "\n",
              cli.output);
    EXPECT_EQ(browser.evaluate("document.getElementById('scene-error').hidden"), true);
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// A field typed into, as a student types: focused, its text replaced, Enter pressed.
void typeInto(Browser& browser, const std::string& field, const std::string& text)
{
    browser.evaluate("(() => { const f = document.querySelector(`input[aria-label='" + field + "']`); f.focus(); f.select(); })()");
    browser.page("Input.insertText", {{"text", text}});
    browser.press("Enter", 13);
}

void pressWithControl(Browser& browser, const std::string& key, int keyCode)
{
    for (const char* type : {"rawKeyDown", "keyUp"})
        browser.page("Input.dispatchKeyEvent", {{"type", type}, {"key", key}, {"code", "Key" + std::string(1, char(std::toupper(key[0])))},
                                                {"windowsVirtualKeyCode", keyCode}, {"modifiers", 2}});
}

// The world view's pixels (the picture the page draws), where a refusal must leave it as it was.
QImage worldView(Browser& browser)
{
    const json box = json::parse(browser.evaluate(
        "JSON.stringify((r => [r.left, r.top, r.width, r.height])(document.getElementById('world').getBoundingClientRect()))")
                                     .get<std::string>());
    return browser.screenshot().copy(box[0].get<int>(), box[1].get<int>(), box[2].get<int>(), box[3].get<int>());
}

TEST_F(WebPage, EditsTheSceneWithTheCoreRefusesBesideTheFieldUndoesAndLinksIt)
{
    // The same edit as a file, for the CLI: the PRP moved to x = 20.
    std::ifstream in(kData + "/scenes/house.json");
    std::stringstream house;
    house << in.rdbuf();
    std::string moved = house.str();
    const std::size_t prp = moved.find("\"prp\": [8, 6, 84]");
    ASSERT_NE(prp, std::string::npos);
    moved.replace(prp, 17, "\"prp\": [20, 6, 84]");
    const fs::path movedFile = *dir_ / "house-prp-20.json";
    std::ofstream(movedFile) << moved;
    const Finished original = viewpipe({"pipeline", QString::fromStdString(kData + "/scenes/house.json"), "--json"});
    const Finished expected = viewpipe({"pipeline", QString::fromStdString(movedFile.string()), "--json"});
    ASSERT_EQ(expected.exitCode, 0) << expected.output;

    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-edit");
    browser.page("Page.navigate", {{"url", "file://" + page.string() + "#stage=3"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'")) << "the core never loaded";
    const std::string json = "document.getElementById('pipeline-json').textContent";

    // A number typed as people type it: the core computes the scene anew, as the CLI does for the same file
    // (with 20); the stage stays.
    const QImage house3 = worldView(browser);
    typeInto(browser, "view.prp[0]", "+20.");
    ASSERT_TRUE(browser.waitFor(json + ".length > 0 && " + json + " + '\\n' !== " + nlohmann::json(original.output).dump()));
    EXPECT_EQ(browser.evaluate(json).get<std::string>() + "\n", expected.output);
    EXPECT_EQ(browser.evaluate("document.body.dataset.stage"), "3");
    EXPECT_EQ(browser.evaluate("document.querySelector(`input[aria-label='view.prp[0]']`).value"), "20");
    // The scene the page holds (its link's) is the core's, the field put in as typed (withTypedField).
    ASSERT_TRUE(browser.waitFor("location.hash.includes('scene=')"));
    EXPECT_EQ(browser.evaluate("(() => { const m = /scene=([^&]*)/.exec(location.hash); return new TextDecoder().decode("
                               "Uint8Array.from(atob(m[1].replace(/-/g, '+').replace(/_/g, '/')), (c) => c.charCodeAt(0))); })()"),
              viewpipe::withTypedField(house.str(), "view.prp[0]", "+20.", true));
    const QImage moved3 = worldView(browser);
    EXPECT_NE(moved3, house3) << "the picture of stage 3 is drawn anew";

    // A refused value: its reason beside its field (the core's field path), the last picture and numbers kept.
    typeInto(browser, "view.vup[1]", "0");
    ASSERT_TRUE(browser.waitFor("!document.getElementById('scene-error').hidden"));
    const std::string reason = browser.evaluate("document.getElementById('scene-error').textContent");
    EXPECT_EQ(reason.rfind("view.vup: ", 0), 0u) << reason;
    EXPECT_EQ(browser.evaluate("document.querySelector(`.field[data-path='view.vup'] .field-error`).textContent"), reason);
    EXPECT_EQ(browser.evaluate("document.querySelector(`input[aria-label='view.vup[1]']`).getAttribute('aria-invalid')"), "true");
    EXPECT_EQ(browser.evaluate(json).get<std::string>() + "\n", expected.output);
    EXPECT_EQ(worldView(browser), moved3) << "a refusal keeps the picture";

    // Undo and redo with the keys, away from the typed field (whose own text Ctrl+Z would undo first). The first
    // Ctrl+Z undoes the refused value alone; the next the last edit taken.
    browser.evaluate("document.activeElement.blur()");
    pressWithControl(browser, "z", 90);
    ASSERT_TRUE(browser.waitFor("document.getElementById('scene-error').hidden"));
    EXPECT_EQ(browser.evaluate("document.querySelector(`input[aria-label='view.vup[1]']`).value"), "1");
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('[aria-invalid]').length"), 0);
    EXPECT_EQ(browser.evaluate(json).get<std::string>() + "\n", expected.output);
    pressWithControl(browser, "z", 90);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(original.output).dump()));
    EXPECT_EQ(browser.evaluate("document.querySelector(`input[aria-label='view.prp[0]']`).value"), "8");
    EXPECT_EQ(browser.evaluate("document.getElementById('scene-error').hidden"), true);
    pressWithControl(browser, "y", 89);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(expected.output).dump()));

    // The link holds the scene (base64url of its JSON, RFC 4648 section 5): opened, it restores scene and stage.
    const std::string hash = browser.evaluate("location.hash");
    const std::size_t at = hash.find("scene=");
    ASSERT_NE(at, std::string::npos) << hash;
    const std::string encoded = hash.substr(at + 6, hash.find('&', at) - at - 6);
    EXPECT_EQ(encoded.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"), std::string::npos);
    const QByteArray scene = QByteArray::fromBase64(QByteArray::fromStdString(encoded),
                                                    QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals);
    EXPECT_EQ(nlohmann::json::parse(scene.toStdString()), nlohmann::json::parse(moved));
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;

    Browser opened(*dir_ / "profile-link");
    opened.page("Page.navigate", {{"url", "file://" + page.string() + hash}});
    ASSERT_TRUE(opened.waitFor("document.body.dataset.core === '1'"));
    EXPECT_EQ(opened.evaluate(json).get<std::string>() + "\n", expected.output);
    EXPECT_EQ(opened.evaluate("document.body.dataset.stage"), "3");
    EXPECT_EQ(opened.evaluate("document.querySelector(`input[aria-label='view.prp[0]']`).value"), "20");
    EXPECT_EQ(worldView(opened), moved3) << "the link shows the edited scene's stage as the edit did";

    // A link pasted into the page open: its scene and its stage.
    const std::string houseLink = QByteArray::fromStdString(house.str())
                                      .toBase64(QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals)
                                      .toStdString();
    opened.evaluate("location.hash = '#stage=2&scene=" + houseLink + "'");
    ASSERT_TRUE(opened.waitFor(json + " + '\\n' === " + nlohmann::json(original.output).dump()));
    EXPECT_EQ(opened.evaluate("document.body.dataset.stage"), "2");
    EXPECT_EQ(opened.evaluate("document.querySelector(`input[aria-label='view.prp[0]']`).value"), "8");

    // Space on the Scene panel's heading opens or closes the panel; it does not play.
    opened.evaluate("document.querySelector('#scene-editor summary').focus()");
    opened.press(" ", 32);
    EXPECT_EQ(opened.evaluate("document.getElementById('play').textContent"), "Play");
    for (const std::string& problem : opened.problems())
        ADD_FAILURE() << problem;
}

// Exact expressions in the Scene panel's fields (issue 46): the core reads them, the page's scene keeps them as
// typed (text in the field, as a scene file holds it) and computes as the CLI does for that file; a bad one is
// refused beside its field with the core's path and reason.
TEST_F(WebPage, TakesExactExpressionsInTheFieldsAndKeepsThemAsTyped)
{
    std::ifstream in(kData + "/scenes/house.json");
    std::stringstream house;
    house << in.rdbuf();
    json exact = json::parse(house.str());
    exact["view"]["prp"][0] = "20*sqrt(2)";
    exact["view"]["prp"][1] = "\u221A2";
    const fs::path exactFile = *dir_ / "house-prp-exact.json";
    std::ofstream(exactFile) << exact.dump(2);
    const Finished expected = viewpipe({"pipeline", QString::fromStdString(exactFile.string()), "--json"});
    ASSERT_EQ(expected.exitCode, 0) << expected.output;

    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-exact");
    browser.page("Page.navigate", {{"url", "file://" + page.string()}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'"));
    const std::string pipelineJson = "document.getElementById('pipeline-json').textContent";
    // PRP as the scene held by the link (its JSON in base64url, as the page writes it) has it.
    const std::string prp = "(() => { const m = /scene=([^&]*)/.exec(location.hash); if (!m) return ''; "
                            "const bytes = Uint8Array.from(atob(m[1].replace(/-/g, '+').replace(/_/g, '/')), (c) => c.charCodeAt(0)); "
                            "return JSON.stringify(JSON.parse(new TextDecoder().decode(bytes)).view.prp); })()";
    const auto field = [](const std::string& path) { return "document.querySelector(`input[aria-label='" + path + "']`)"; };

    typeInto(browser, "view.prp[0]", "20*sqrt(2)");
    ASSERT_TRUE(browser.waitFor(prp + " === '[\"20*sqrt(2)\",6,84]'")) << browser.evaluate(prp);
    typeInto(browser, "view.prp[1]", "\u221A2");
    ASSERT_TRUE(browser.waitFor(prp + " === '[\"20*sqrt(2)\",\"\u221A2\",84]'")) << browser.evaluate(prp);
    EXPECT_EQ(browser.evaluate(pipelineJson).get<std::string>() + "\n", expected.output);
    // The fields show the text typed, PRP's three still one row, and the expressions are numbers' fields.
    EXPECT_EQ(browser.evaluate(field("view.prp[0]") + ".value"), "20*sqrt(2)");
    EXPECT_EQ(browser.evaluate(field("view.prp[1]") + ".value"), "\u221A2");
    EXPECT_EQ(browser.evaluate("document.querySelectorAll(`.field[data-path='view.prp'] input`).length"), 3);
    EXPECT_EQ(browser.evaluate(field("view.prp[0]") + ".dataset.kind"), "number");

    // A bad one: refused beside PRP with its path and reason; the scene keeps the expressions.
    typeInto(browser, "view.prp[1]", "1/0");
    ASSERT_TRUE(browser.waitFor("!document.getElementById('scene-error').hidden"));
    EXPECT_EQ(browser.evaluate("document.querySelector(`.field[data-path='view.prp'] .field-error`).textContent"),
              "view.prp[1]: division by zero at character 3 of \"1/0\"");
    EXPECT_EQ(browser.evaluate(prp), "[\"20*sqrt(2)\",\"\u221A2\",84]");
    EXPECT_EQ(browser.evaluate(pipelineJson).get<std::string>() + "\n", expected.output);

    // Save scene writes them as typed.
    browser.call("Browser.setDownloadBehavior", {{"behavior", "allow"}, {"downloadPath", (*dir_ / "exact-saved").string()}});
    browser.evaluate("document.getElementById('save-scene').click()");
    const fs::path saved = *dir_ / "exact-saved" / "foley-s-house.json";
    ASSERT_TRUE(waitForFile(saved)) << "the scene is downloaded";
    std::ifstream savedIn(saved);
    EXPECT_EQ(json::parse(savedIn)["view"]["prp"], json::parse("[\"20*sqrt(2)\", \"\u221A2\", 84]"));

    // A number typed over an expression is a number in the scene again.
    typeInto(browser, "view.prp[0]", "8");
    ASSERT_TRUE(browser.waitFor(prp + " === '[8,\"\u221A2\",84]'")) << browser.evaluate(prp);
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

TEST_F(WebPage, OpensAndDropsScenesAndMeshesReadByTheCore)
{
    // A scene of one tetrahedron, and the same scene with a truncated PLY added: as files, for the CLI.
    const fs::path folder = *dir_ / "opened";
    fs::create_directories(folder);
    std::ofstream(folder / "tetrahedron.obj") << "v 0 0 0\nv 40 0 0\nv 0 40 0\nv 0 0 40\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const std::string truncatedPly = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n") +
                                     "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n" +
                                     "end_header\n" + std::string(2, '\0');
    std::ofstream(folder / "broken.ply", std::ios::binary) << truncatedPly;
    const std::string view = R"("view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
                                "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})";
    std::ofstream(folder / "tetrahedron.json")
        << R"({"name": "A tetrahedron", )" << view << R"(, "objects": [{"type": "mesh", "path": "tetrahedron.obj"}], "effects": []})";
    std::ofstream(folder / "with-broken.json")
        << R"({"name": "A tetrahedron", )" << view
        << R"(, "objects": [{"type": "mesh", "path": "tetrahedron.obj"}, {"type": "mesh", "path": "broken.ply"}], "effects": []})";
    const Finished expected = viewpipe({"pipeline", QString::fromStdString((folder / "tetrahedron.json").string()), "--json"});
    ASSERT_EQ(expected.exitCode, 0) << expected.output;
    const std::string broken = (folder / "with-broken.json").string();
    const Finished refused = viewpipe({"pipeline", QString::fromStdString(broken), "--json"});
    ASSERT_EQ(refused.exitCode, 2) << refused.output;
    ASSERT_EQ(refused.output.rfind(broken + ": ", 0), 0u) << refused.output;
    const std::string reason = refused.output.substr(broken.size() + 2, refused.output.size() - broken.size() - 3);

    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-open");
    browser.page("Page.navigate", {{"url", "file://" + page.string()}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'")) << "the core never loaded";

    // Opened with the file picker, as a student picks a scene and its mesh: the core reads both.
    const int root = browser.page("DOM.getDocument")["root"]["nodeId"];
    const int picker = browser.page("DOM.querySelector", {{"nodeId", root}, {"selector", "#open-files"}})["nodeId"];
    browser.page("DOM.setFileInputFiles", {{"nodeId", picker},
                                           {"files", {(folder / "tetrahedron.json").string(), (folder / "tetrahedron.obj").string()}}});
    const std::string json = "document.getElementById('pipeline-json').textContent";
    ASSERT_TRUE(browser.waitFor("document.getElementById('title').textContent === 'A tetrahedron'"));
    EXPECT_EQ(browser.evaluate(json).get<std::string>() + "\n", expected.output);
    const QImage tetrahedron = worldView(browser);
    const std::string linkNote = "document.getElementById('link-note').textContent";
    EXPECT_NE(browser.evaluate(linkNote).get<std::string>(), "") << "a scene with meshes is saved, not linked";

    // Undone, the house comes back with its own link; redone, the tetrahedron with its mesh.
    const std::string house = viewpipe({"pipeline", QString::fromStdString(kData + "/scenes/house.json"), "--json"}).output;
    browser.evaluate("document.activeElement.blur()");
    pressWithControl(browser, "z", 90);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(house).dump()));
    EXPECT_EQ(browser.evaluate(linkNote), "");
    pressWithControl(browser, "y", 89);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(expected.output).dump()));
    EXPECT_NE(browser.evaluate(linkNote).get<std::string>(), "");
    EXPECT_EQ(worldView(browser), tetrahedron);

    // A hostile mesh dropped: refused with the CLI's message, the page alive, the picture and numbers kept.
    browser.evaluate(R"((() => {
        const bytes = Uint8Array.from(atob(')" + QByteArray::fromStdString(truncatedPly).toBase64().toStdString() + R"('), (c) => c.charCodeAt(0));
        const dropped = new DataTransfer();
        dropped.items.add(new File([bytes], 'broken.ply'));
        document.querySelector('main').dispatchEvent(new DragEvent('drop', { dataTransfer: dropped, bubbles: true, cancelable: true }));
    })())");
    ASSERT_TRUE(browser.waitFor("!document.getElementById('scene-error').hidden"));
    EXPECT_EQ(browser.evaluate("document.getElementById('scene-error').textContent"), reason);
    EXPECT_EQ(browser.evaluate("document.getElementById('editor-error').textContent"), reason);
    EXPECT_EQ(browser.evaluate(json).get<std::string>() + "\n", expected.output);
    EXPECT_EQ(worldView(browser), tetrahedron);
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('#stage-list li').length"), 6) << "the page still answers";

    // A scene naming its mesh in another folder (../meshes/letter-f.obj), picked with the mesh: the
    // mesh goes where the scene looks for it.
    const std::string letterF = viewpipe({"pipeline", QString::fromStdString(kData + "/scenes/letter-f.json"), "--json"}).output;
    browser.page("DOM.setFileInputFiles", {{"nodeId", picker},
                                           {"files", {kData + "/scenes/letter-f.json", kData + "/meshes/letter-f.obj"}}});
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(letterF).dump()))
        << browser.evaluate("document.getElementById('scene-error').textContent");
    EXPECT_TRUE(browser.evaluate("document.getElementById('scene-error').hidden").get<bool>());
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// The camera as code, as the app's Code panel shows it (the core writes it): a number dragged is one
// undoable edit whose scene is the CLI's with that value; ↑ steps it; pasted code sets the camera; a
// preset opens as the app opens it. All offline.
TEST_F(WebPage, TheCameraAsCodeIsDraggedSteppedAndPasted)
{
    const fs::path folder = *dir_ / "opengl";
    const Finished exported = viewpipe({"export", QString::fromStdString(kData + "/scenes/opengl-perspective.json"), "--out",
                                        QString::fromStdString(folder.string()), "--format", "html", "--quiet"});
    ASSERT_EQ(exported.exitCode, 0) << exported.output;
    std::ifstream in(kData + "/scenes/opengl-perspective.json");
    std::stringstream original;
    original << in.rdbuf();
    // The same scene with another field of view, for the CLI.
    const auto withFovy = [&](const std::string& fovy) {
        std::string text = original.str();
        const std::size_t at = text.find("\"fovy_deg\": 40");
        text.replace(at, 14, "\"fovy_deg\": " + fovy);
        const fs::path file = folder / ("fovy-" + fovy + ".json");
        std::ofstream(file) << text;
        return viewpipe({"pipeline", QString::fromStdString(file.string()), "--json"}).output;
    };

    // Offline, as in a lecture hall without a network: the page needs none.
    Browser browser(*dir_ / "profile-code");
    browser.page("Network.enable");
    browser.page("Network.emulateNetworkConditions",
                 {{"offline", true}, {"latency", 0}, {"downloadThroughput", -1}, {"uploadThroughput", -1}});
    browser.page("Page.navigate", {{"url", "file://" + (folder / "scene.html").string()}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'")) << "the core never loaded";
    browser.evaluate("document.getElementById('code-editor').open = true");
    const std::string json = "document.getElementById('pipeline-json').textContent";
    const std::string codeText = "document.getElementById('camera-code').textContent";
    ASSERT_NE(browser.evaluate(codeText).get<std::string>().find("gluPerspective(40, 1.5, 30, 110)"), std::string::npos)
        << browser.evaluate(codeText);

    // Dragged 50 pixels right: 40 moves by 0.1 a pixel (the app's step), to 45, in one undoable edit.
    const std::string fovy = "document.querySelector(`#camera-code [aria-label^='fovy']`)";
    browser.evaluate(fovy + ".scrollIntoView({ block: 'center' })");
    const nlohmann::json box = nlohmann::json::parse(browser.evaluate("JSON.stringify((() => { const r = " + fovy +
                                                  ".getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; })())")
                                     .get<std::string>());
    const double x = box[0], y = box[1];
    const std::string fovyField = "document.querySelector(`input[aria-label='camera.projection.fovy_deg']`)";
    browser.evaluate("window.fovyField = " + fovyField);
    browser.page("Input.dispatchMouseEvent", {{"type", "mousePressed"}, {"x", x}, {"y", y}, {"button", "left"}, {"clickCount", 1}});
    for (int dx = 10; dx <= 50; dx += 10) {
        browser.page("Input.dispatchMouseEvent", {{"type", "mouseMoved"}, {"x", x + dx}, {"y", y}, {"button", "left"}, {"buttons", 1}});
        browser.evaluate("new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))");
    }
    // The link is written once the drag ends, not at every move: until then it names the page's own scene.
    EXPECT_EQ(browser.evaluate("location.hash.includes('scene=')"), false) << browser.evaluate("location.hash");
    browser.page("Input.dispatchMouseEvent", {{"type", "mouseReleased"}, {"x", x + 50}, {"y", y}, {"button", "left"}, {"clickCount", 1}});
    const std::string at45 = withFovy("45");
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(at45).dump()));
    EXPECT_NE(browser.evaluate(codeText).get<std::string>().find("gluPerspective(45, 1.5, 30, 110)"), std::string::npos);
    EXPECT_EQ(browser.evaluate(fovyField + ".value"), "45");
    EXPECT_EQ(browser.evaluate("window.fovyField === " + fovyField), true) << "the Scene panel's rows are kept, their values set";
    // The link written after the drag holds the value dragged to.
    EXPECT_EQ(browser.evaluate("JSON.parse(new TextDecoder().decode(Uint8Array.from(atob(new URLSearchParams(location.hash.slice(1))"
                               ".get('scene').replace(/-/g, '+').replace(/_/g, '/')), (c) => c.charCodeAt(0)))).camera.projection.fovy_deg"),
              45);
    browser.evaluate("document.activeElement.blur()");
    pressWithControl(browser, "z", 90);
    const std::string at40 = viewpipe({"pipeline", QString::fromStdString(kData + "/scenes/opengl-perspective.json"), "--json"}).output;
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(at40).dump())) << "one Ctrl+Z undoes the whole drag";
    EXPECT_EQ(browser.evaluate("document.getElementById('undo').disabled"), true);

    // ↑ on the number steps it once.
    browser.evaluate(fovy + ".focus()");
    browser.press("ArrowUp", 38);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(withFovy("40.1")).dump()));

    // Pasted code sets the camera; code that names nothing is refused with the core's reason.
    browser.evaluate("document.getElementById('code-paste').value = 'gluPerspective(60, 1.5, 30, 110)'");
    browser.evaluate("document.getElementById('apply-code').click()");
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(withFovy("60")).dump()));
    browser.evaluate("document.getElementById('code-paste').value = 'hello()'");
    browser.evaluate("document.getElementById('apply-code').click()");
    ASSERT_TRUE(browser.waitFor("!document.getElementById('code-error').hidden"));
    EXPECT_EQ(browser.evaluate("document.getElementById('code-error').textContent").get<std::string>().rfind("code: ", 0), 0u);

    // A preset, as the app's File > Presets opens it: the CLI's numbers for its file, and undoable.
    const std::string ortho = kData + "/scenes/opengl-ortho.json";
    std::ifstream orthoIn(ortho);
    const std::string orthoName = nlohmann::json::parse(orthoIn)["name"];
    EXPECT_EQ(browser.evaluate("(() => { const picker = document.getElementById('presets'); const option = [...picker.options].find("
                               "(o) => o.text === " + nlohmann::json(orthoName).dump() + "); if (!option) return false; "
                               "picker.value = option.value; picker.dispatchEvent(new Event('change')); return true; })()"),
              true) << "the presets offer " << orthoName;
    const std::string orthoJson = viewpipe({"pipeline", QString::fromStdString(ortho), "--json"}).output;
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(orthoJson).dump()));
    EXPECT_EQ(browser.evaluate("document.getElementById('title').textContent"), orthoName);
    pressWithControl(browser, "z", 90);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(withFovy("60")).dump()));
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// The settings picked from a list, as in the app's Parameters: the core rewrites the scene and the CLI computes the
// same numbers for it; gluPerspective switched to glFrustum keeps the projection (its reference page: gluPerspective
// is glFrustum with top = zNear · tan(fovy / 2)).
TEST_F(WebPage, ChoosesTheApiAndTheProjectionTypeAsTheAppDoes)
{
    const fs::path folder = *dir_ / "choices";
    const std::string scene = kData + "/scenes/opengl-perspective.json";
    const Finished exported = viewpipe({"export", QString::fromStdString(scene), "--out",
                                        QString::fromStdString(folder.string()), "--format", "html", "--quiet"});
    ASSERT_EQ(exported.exitCode, 0) << exported.output;
    const std::string original = viewpipe({"pipeline", QString::fromStdString(scene), "--json"}).output;

    Browser browser(*dir_ / "profile-choices");
    browser.page("Page.navigate", {{"url", "file://" + (folder / "scene.html").string()}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'")) << "the core never loaded";
    const std::string json = "document.getElementById('pipeline-json').textContent";
    const auto choose = [&](const std::string& field, int index) {
        browser.evaluate("(() => { const s = document.getElementById('field-" + field + "'); s.selectedIndex = " +
                         std::to_string(index) + "; s.dispatchEvent(new Event('change')); })()");
    };
    const auto selected = [&](const std::string& field) {
        return browser.evaluate("document.getElementById('field-" + field + "').selectedOptions[0].text").get<std::string>();
    };
    EXPECT_EQ(selected("camera.projection.type"), "gluPerspective");
    EXPECT_EQ(selected("camera.api"), "OpenGL");

    choose("camera.projection.type", 0);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' !== " + nlohmann::json(original).dump()));
    EXPECT_EQ(selected("camera.projection.type"), "glFrustum");
    EXPECT_EQ(browser.evaluate("!!document.querySelector(`input[aria-label='camera.projection.left']`) && "
                               "!document.querySelector(`input[aria-label='camera.projection.fovy_deg']`)"),
              true) << "the fields are glFrustum's";
    const auto composite = [](const std::string& text) { return nlohmann::json::parse(text)["composite"]; };
    const nlohmann::json before = composite(original), after = composite(browser.evaluate(json).get<std::string>());
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(after[r][c].get<double>(), before[r][c].get<double>(),
                        1e-14 * std::max(1.0, std::abs(before[r][c].get<double>())))
                << "composite(" << r << ", " << c << ")";
    // The scene the page holds now (its link), computed by the CLI: the page's numbers, digit for digit.
    const std::string hash = browser.evaluate("location.hash");
    const std::size_t at = hash.find("scene=");
    ASSERT_NE(at, std::string::npos) << hash;
    const fs::path frustumFile = folder / "frustum.json";
    std::ofstream(frustumFile) << QByteArray::fromBase64(QByteArray::fromStdString(hash.substr(at + 6, hash.find('&', at) - at - 6)),
                                                         QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals)
                                      .toStdString();
    EXPECT_EQ(browser.evaluate(json).get<std::string>() + "\n",
              viewpipe({"pipeline", QString::fromStdString(frustumFile.string()), "--json"}).output);

    // Undone, then Vulkan chosen: the CLI's numbers for the file with "api": "vulkan".
    browser.evaluate("document.activeElement.blur()");
    pressWithControl(browser, "z", 90);
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(original).dump()));
    EXPECT_EQ(selected("camera.projection.type"), "gluPerspective");
    choose("camera.api", 2);
    std::ifstream in(scene);
    nlohmann::ordered_json vulkan = nlohmann::ordered_json::parse(in);
    vulkan["camera"]["api"] = "vulkan";
    const fs::path vulkanFile = folder / "vulkan.json";
    std::ofstream(vulkanFile) << vulkan.dump(2);
    const std::string expected = viewpipe({"pipeline", QString::fromStdString(vulkanFile.string()), "--json"}).output;
    ASSERT_TRUE(browser.waitFor(json + " + '\\n' === " + nlohmann::json(expected).dump()));
    EXPECT_EQ(selected("camera.api"), "Vulkan");
    EXPECT_EQ(selected("camera.projection.type"), "perspective (field of view)") << "found: OpenGL's call shown for a Vulkan camera";
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

TEST_F(WebPage, OnHalfALaptopScreenFoldsItsPanelsNamesItsViewsAndSavesTheView)
{
    const fs::path folder = *dir_ / "opengl";
    const Finished run = viewpipe({"export", QString::fromStdString(kData + "/scenes/opengl-perspective.json"), "--out",
                                   QString::fromStdString(folder.string()), "--format", "html", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    Browser browser(*dir_ / "profile-laptop", 800, 600);
    ASSERT_TRUE(browser.openWithCore("file://" + (folder / "scene.html").string() + "#stage=3"));
    const auto box = [&](const std::string& selector) {
        return json::parse(browser.evaluate("JSON.stringify((r => ({left: r.left, top: r.top, width: r.width, bottom: r.bottom}))"
                                            "(document.querySelector('" + selector + "').getBoundingClientRect()))")
                               .get<std::string>());
    };

    // The world view the window's width; the camera's view and the panels under it, not beside it.
    const json world = box("#world-canvas");
    EXPECT_GE(world["width"].get<double>(), 0.6 * 800) << world;
    for (const char* panel : {"#projected-canvas", "nav", "#matrices"})
        EXPECT_GE(box(panel)["top"].get<double>(), world["bottom"].get<double>() - 1) << panel;

    // The vanishing lines (the overlay's pixels) inside the window, the blue rectangle the camera's view draws.
    const json marks = json::parse(browser.evaluate(R"(JSON.stringify((() => {
        const bounds = (canvas, isMarked) => {
          const copy = document.createElement('canvas');
          copy.width = canvas.width; copy.height = canvas.height;
          const context = copy.getContext('2d');
          context.drawImage(canvas, 0, 0);
          const pixels = context.getImageData(0, 0, copy.width, copy.height).data;
          const b = { left: Infinity, top: Infinity, right: -Infinity, bottom: -Infinity, count: 0 };
          for (let y = 0; y < copy.height; ++y)
            for (let x = 0; x < copy.width; ++x) {
              if (!isMarked(pixels, 4 * (y * copy.width + x))) continue;
              b.left = Math.min(b.left, x); b.right = Math.max(b.right, x);
              b.top = Math.min(b.top, y); b.bottom = Math.max(b.bottom, y); ++b.count;
            }
          return b;
        };
        const blue = (p, k) => p[k] < 40 && Math.abs(p[k + 1] - 102) < 40 && p[k + 2] > 170; // the window's line
        return { window: bounds(document.getElementById('projected-canvas'), blue),
                 lines: bounds(document.getElementById('projected-overlay'), (p, k) => p[k + 3] > 0) };
      })()))").get<std::string>());
    const json& window = marks["window"];
    const json& lines = marks["lines"];
    ASSERT_GT(window["count"].get<int>(), 400) << marks;
    ASSERT_GT(lines["count"].get<int>(), 400) << "the vanishing lines are drawn: " << marks;
    EXPECT_GE(lines["left"].get<int>(), window["left"].get<int>() - 1) << marks;
    EXPECT_LE(lines["right"].get<int>(), window["right"].get<int>() + 1) << marks;
    EXPECT_GE(lines["top"].get<int>(), window["top"].get<int>() - 1) << marks;
    EXPECT_LE(lines["bottom"].get<int>(), window["bottom"].get<int>() + 1) << marks;

    // Each canvas named with the stage shown and what it shows (an overlay is its view's labels: hidden from the
    // names' tree), named anew when the stage changes.
    const std::string names = R"(JSON.stringify([...document.querySelectorAll('canvas')].map((c) =>
        c.getAttribute('aria-hidden') === 'true' ? 'hidden' : c.getAttribute('role') + ': ' + c.getAttribute('aria-label'))))";
    const auto expectNamed = [&](const std::string& stage) {
        const json named = json::parse(browser.evaluate(names).get<std::string>());
        ASSERT_EQ(named.size(), 4u) << named;
        EXPECT_EQ(named[0].get<std::string>().rfind("img: World view, stage " + stage, 0), 0u) << named;
        EXPECT_EQ(named[1], "hidden");
        EXPECT_EQ(named[2].get<std::string>().rfind("img: What the camera sees, beside stage " + stage, 0), 0u) << named;
        EXPECT_NE(named[2].get<std::string>().find("vanishing lines"), std::string::npos) << named;
        EXPECT_EQ(named[3], "hidden");
    };
    expectNamed("3. S sub fovy");
    browser.press("ArrowRight", 39);
    ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '4' && !document.body.dataset.moving"));
    expectNamed("4. P sub depth");

    // The view saved as shown: a PNG of the drawing with its labels, an SVG of the core's figure for it.
    browser.call("Browser.setDownloadBehavior", {{"behavior", "allow"}, {"downloadPath", folder.string()}});
    const std::string name = "opengl-camera-glulookat-and-gluperspective-stage-4";
    browser.evaluate("document.getElementById('save-png').click()");
    ASSERT_TRUE(waitForFile(folder / (name + ".png"))) << "the PNG is downloaded";
    const QImage png(QString::fromStdString((folder / (name + ".png")).string()));
    EXPECT_EQ(png.width(), world["width"].get<int>());
    const std::vector<bool> ink = drawn(png);
    EXPECT_GT(std::count(ink.begin(), ink.end(), true), 5000) << "the PNG holds the picture";
    browser.evaluate("document.getElementById('save-svg').click()");
    ASSERT_TRUE(waitForFile(folder / (name + ".svg"))) << "the SVG is downloaded";
    browser.page("Page.navigate", {{"url", "file://" + (folder / (name + ".svg")).string()}});
    ASSERT_TRUE(browser.waitFor("document.readyState === 'complete'"));
    EXPECT_EQ(browser.evaluate("document.documentElement.localName + ' ' + !document.querySelector('parsererror')"), "svg true");
    EXPECT_EQ(browser.evaluate("document.querySelector('title').textContent.startsWith('World view, stage 4. P sub depth')"), true);
    EXPECT_GT(browser.evaluate("document.querySelectorAll('polygon').length").get<int>(), 10);
    EXPECT_GT(browser.evaluate("document.querySelectorAll('polyline').length").get<int>(), 10);
    EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('text')].some((t) => t.textContent === 'CW')"), true);
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// Every stage at once (#layout=storyboard): a cell a stage, each drawn, under its header (the arrow from the one
// before and its matrix's name) and over its footer (the traced point in its stage's coordinates: Foley's house,
// PRP (8, 6, 84), T(-PRP) takes the corner (0, 0, 54) to (-8, -6, -30), as tests/report/storyboard_test.cpp);
// turned together, drawn anew on an edit, and the page as it was once switched back.
TEST_F(WebPage, ShowsEveryStageAtOnceAsTheCoreLaysThemOut)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-storyboard", 1280, 720);
    browser.page("Page.navigate", {{"url", "file://" + page.string() + "#layout=storyboard"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1' && document.querySelectorAll('#storyboard .cell').length === 6"));
    EXPECT_EQ(browser.evaluate("getComputedStyle(document.getElementById('world')).display"), "none");
    EXPECT_EQ(browser.evaluate("document.getElementById('layout').getAttribute('aria-pressed')"), "true");
    const auto rect = [&](const std::string& selector) {
        return json::parse(browser.evaluate("JSON.stringify((r => [Math.round(r.left), Math.round(r.top), Math.round(r.width), "
                                            "Math.round(r.height)])(document.querySelector(`" + selector + "`).getBoundingClientRect()))")
                               .get<std::string>());
    };
    // Each stage's picture on screen, all at once, drawn, and no two alike.
    const auto pictures = [&] {
        const QImage shot = browser.screenshot();
        std::vector<QImage> cells;
        for (int k = 0; k < 6; ++k) {
            const json r = rect(".cell[data-stage='" + std::to_string(k) + "'] canvas");
            EXPECT_TRUE(r[0] >= 0 && r[1] >= 0 && r[0].get<int>() + r[2].get<int>() <= 1280 && r[1].get<int>() + r[3].get<int>() <= 720 &&
                        r[2] > 100 && r[3] > 50) << k << ": " << r;
            cells.push_back(shot.copy(r[0], r[1], r[2], r[3]));
        }
        return cells;
    };
    // The house's VRP is the origin and its VPN z: T(-VRP) and R move nothing, and stages 0 to 2 look alike, as in
    // the native storyboard; each later matrix moves the scene.
    const std::vector<QImage> before = pictures();
    for (int k = 0; k < 6; ++k) {
        const std::vector<bool> ink = drawn(before[std::size_t(k)]);
        EXPECT_GT(std::count(ink.begin(), ink.end(), true), 500) << "stage " << k << " is drawn";
        for (int j = 2; j < k; ++j)
            EXPECT_NE(before[std::size_t(k)], before[std::size_t(j)]) << "stages " << j << " and " << k;
    }
    // The headers name each stage's matrix (typeset from the core's math), each after an arrow but the world's.
    EXPECT_EQ(browser.evaluate("document.querySelector(`.cell[data-stage='0'] .header`).textContent"), "0. World");
    const char* symbols[] = {"T(-\\mathit{VRP})", "R", "T(-\\mathit{PRP})", "\\mathit{SH}_{\\mathrm{per}}", "S_{\\mathrm{per}}"};
    for (int k = 1; k <= 5; ++k)
        EXPECT_EQ(browser.evaluate("document.querySelector(`.cell[data-stage='" + std::to_string(k) + "'] .header annotation`).textContent"),
                  symbols[k - 1]);
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('#storyboard-arrows polygon').length"), 5);
    // The traced point's coordinates in each stage's space, and in each canvas's name.
    const auto footer = [&](int k) {
        return browser.evaluate("document.querySelector(`.cell[data-stage='" + std::to_string(k) + "'] .footer`).textContent")
            .get<std::string>();
    };
    EXPECT_EQ(footer(0), "traced (0, 0, 54)");
    EXPECT_EQ(footer(3), "traced (\u22128, \u22126, \u221230)");
    EXPECT_NE(browser.evaluate("document.querySelector(`.cell[data-stage='3'] canvas`).getAttribute('aria-label')").get<std::string>()
                  .find("(\u22128, \u22126, \u221230)"),
              std::string::npos);

    // Dragging one cell turns every one.
    const json from = rect(".cell[data-stage='1'] canvas");
    const double x = from[0].get<double>() + from[2].get<double>() / 2, y = from[1].get<double>() + from[3].get<double>() / 2;
    browser.page("Input.dispatchMouseEvent", {{"type", "mousePressed"}, {"x", x}, {"y", y}, {"button", "left"}, {"clickCount", 1}});
    for (int step = 1; step <= 4; ++step)
        browser.page("Input.dispatchMouseEvent", {{"type", "mouseMoved"}, {"x", x + 15 * step}, {"y", y}, {"button", "left"}, {"buttons", 1}});
    browser.page("Input.dispatchMouseEvent", {{"type", "mouseReleased"}, {"x", x + 60}, {"y", y}, {"button", "left"}, {"clickCount", 1}});
    ASSERT_TRUE(browser.waitFor("location.hash.includes('yaw=')"));
    const std::vector<QImage> turned = pictures();
    for (const int k : {0, 4, 5})
        EXPECT_NE(turned[std::size_t(k)], before[std::size_t(k)]) << "stage " << k << " turns with stage 1";
    browser.press("0", 48); // the view back

    // An edit redraws every cell: the PRP at x = 20 takes the corner to (-20, -6, -30) after T(-PRP).
    const std::vector<QImage> rest = pictures();
    typeInto(browser, "view.prp[0]", "20");
    ASSERT_TRUE(browser.waitFor("document.querySelector(`.cell[data-stage='3'] .footer`).textContent.includes('20')"));
    EXPECT_EQ(footer(3), "traced (\u221220, \u22126, \u221230)");
    EXPECT_EQ(footer(0), "traced (0, 0, 54)");
    const std::vector<QImage> edited = pictures();
    for (int k = 1; k <= 5; ++k) // the world's own picture does not change with the camera's PRP; every later one does
        EXPECT_NE(edited[std::size_t(k)], rest[std::size_t(k)]) << "stage " << k << " drawn anew";

    // Switched back from the page (its button, keyboard-focusable) and by the link: the page as it was.
    browser.evaluate("document.getElementById('layout').focus()");
    browser.press("Enter", 13);
    ASSERT_TRUE(browser.waitFor("document.getElementById('storyboard').hidden"));
    EXPECT_EQ(browser.evaluate("location.hash.includes('layout')"), false);
    EXPECT_GT(rect("#world-canvas")[2].get<int>(), 300);
    EXPECT_GT(rect("#projected-canvas")[2].get<int>(), 200);
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('#storyboard .cell').length > 0 && "
                               "document.querySelector('#storyboard .cell').getClientRects().length"), 0);
    browser.evaluate("location.hash = 'layout=storyboard'");
    ASSERT_TRUE(browser.waitFor("!document.getElementById('storyboard').hidden"));
    browser.evaluate("location.hash = 'layout=stages'");
    ASSERT_TRUE(browser.waitFor("document.getElementById('storyboard').hidden && "
                                "getComputedStyle(document.getElementById('world')).display !== 'none'"));
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// What is drawn is the reader's, as export's --hide, --legend and --zoom: a toggle a name the core lists, each
// labelled and reached by the keyboard; the core draws the scene without what is left out (its display list:
// the house's, less its projectors, counted by the core here); the link keeps the choices.
TEST_F(WebPage, TheReaderChoosesWhatIsDrawnAndTheLinkKeepsIt)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-choices");
    ASSERT_TRUE(browser.openWithCore("file://" + page.string() + "#stage=3"));
    const auto house = viewpipe::evaluateScene(viewpipe::loadScene(kData + "/scenes/house.json"));
    const long all = long(house->primitives.size());
    const long projectors = std::count_if(house->primitives.begin(), house->primitives.end(),
                                          [](const viewpipe::Primitive& p) { return p.element == viewpipe::Element::Projectors; });
    ASSERT_GT(projectors, 0);
    EXPECT_EQ(browser.evaluate("window.viewpipe.primitives()").get<long>(), all);

    // A toggle a name, as the CLI's --hide lists them, each in its label.
    json names = json::array();
    for (const std::string& name : viewpipe::hideNames())
        names.push_back({name, viewpipe::hideTitle(name)});
    EXPECT_EQ(json::parse(browser.evaluate("JSON.stringify([...document.querySelectorAll('#leave-out input[type=checkbox]')]"
                                           ".map((box) => [box.value, box.closest('label').textContent.trim()]))")
                              .get<std::string>()),
              names);
    const auto legendTexts = [&] {
        return browser.evaluate("document.getElementById('legend').hidden ? 'hidden' : document.getElementById('legend').textContent")
            .get<std::string>();
    };
    ASSERT_NE(legendTexts().find("projectors"), std::string::npos);
    const std::string drawn = "document.getElementById('drawn')";
    browser.evaluate(drawn + ".open = true");

    // Projectors left out with the keyboard: the core's list without them, the legend's line gone, the link says so.
    browser.evaluate("document.querySelector('#leave-out input[value=projectors]').focus()");
    browser.press(" ", 32);
    ASSERT_TRUE(browser.waitFor("location.hash.includes('hide=projectors')"));
    EXPECT_EQ(browser.evaluate("window.viewpipe.primitives()").get<long>(), all - projectors);
    EXPECT_EQ(legendTexts().find("projectors"), std::string::npos) << legendTexts();
    EXPECT_NE(legendTexts().find("window"), std::string::npos) << legendTexts();

    // The legend below the stage (the core's layout): its box in the lower part of the view.
    const auto legendBox = [&] {
        return json::parse(browser.evaluate("JSON.stringify((r => [r.left, r.top, r.right, r.bottom])"
                                            "(document.getElementById('legend').getBoundingClientRect()))")
                               .get<std::string>());
    };
    const json beside = legendBox();
    browser.evaluate("(s => { s.value = 'below'; s.dispatchEvent(new Event('change')); })(document.getElementById('legend-place'))");
    ASSERT_TRUE(browser.waitFor("location.hash.includes('legend=below')"));
    const json below = legendBox();
    const json world = json::parse(browser.evaluate("JSON.stringify((r => [r.top, r.bottom])"
                                                    "(document.getElementById('world').getBoundingClientRect()))").get<std::string>());
    EXPECT_NE(below, beside);
    EXPECT_GT(below[1].get<double>(), (world[0].get<double>() + world[1].get<double>()) / 2) << below << " in " << world;

    // The caption, the ticks' numbers and the legend left out.
    const std::string ticks = "window.viewpipe.restLabels().filter((label) => label.minor).length";
    EXPECT_GT(browser.evaluate(ticks).get<int>(), 0);
    EXPECT_NE(browser.evaluate("document.getElementById('caption').textContent").get<std::string>(), "");
    for (const char* name : {"caption", "ticks", "legend"})
        browser.evaluate(std::string("document.querySelector('#leave-out input[value=") + name + "]').click()");
    ASSERT_TRUE(browser.waitFor("location.hash.includes('hide=caption%2Clegend%2Cprojectors%2Cticks')"))
        << browser.evaluate("location.hash");
    EXPECT_EQ(browser.evaluate(ticks).get<int>(), 0);
    EXPECT_EQ(browser.evaluate("document.getElementById('caption').textContent"), "");
    EXPECT_EQ(legendTexts(), "hidden");

    // The link opened anew: the same choices made, the same drawn.
    const std::string link = browser.evaluate("location.href");
    browser.page("Page.navigate", {{"url", "about:blank"}});
    browser.page("Page.navigate", {{"url", link}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1' && document.body.dataset.core === '1' && "
                                "window.viewpipe.primitives() < " + std::to_string(all)));
    EXPECT_EQ(browser.evaluate("window.viewpipe.primitives()").get<long>(), all - projectors);
    EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('#leave-out input:checked')].map((box) => box.value).join()"),
              "projectors,legend,caption,ticks");
    EXPECT_EQ(browser.evaluate("document.getElementById('legend-place').value"), "below");
    EXPECT_EQ(legendTexts(), "hidden");
    EXPECT_EQ(browser.evaluate(ticks).get<int>(), 0);
    // Everything back: the whole list again.
    for (const char* name : {"projectors", "legend", "caption", "ticks"})
        browser.evaluate(std::string("document.querySelector('#leave-out input[value=") + name + "]').click()");
    ASSERT_TRUE(browser.waitFor("!location.hash.includes('hide=')"));
    EXPECT_EQ(browser.evaluate("window.viewpipe.primitives()").get<long>(), all);
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// A page made with export's --hide, --legend and --zoom starts from those choices, its controls saying so; a reader's
// first choice keeps them (it brought back what the export left out), and taking one back draws it again.
TEST_F(WebPage, APageMadeWithChoicesStartsFromThem)
{
    const fs::path out = *dir_ / "house-chosen";
    const Finished run = viewpipe({"export", QString::fromStdString(kData + "/scenes/house.json"), "--out", QString::fromStdString(out.string()),
                                   "--format", "html", "--hide", "projectors", "--legend", "below", "--zoom", "1.5", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    Browser browser(*dir_ / "profile-chosen");
    ASSERT_TRUE(browser.openWithCore("file://" + (out / "scene.html").string() + "#stage=3"));
    const auto house = viewpipe::evaluateScene(viewpipe::loadScene(kData + "/scenes/house.json"));
    const long all = long(house->primitives.size());
    const long projectors = std::count_if(house->primitives.begin(), house->primitives.end(),
                                          [](const viewpipe::Primitive& p) { return p.element == viewpipe::Element::Projectors; });
    const std::string checked = "[...document.querySelectorAll('#leave-out input:checked')].map((box) => box.value).join()";
    EXPECT_EQ(browser.evaluate("window.viewpipe.primitives()").get<long>(), all - projectors);
    EXPECT_EQ(browser.evaluate(checked), "projectors");
    EXPECT_EQ(browser.evaluate("document.getElementById('legend-place').value"), "below");
    EXPECT_EQ(browser.evaluate("document.getElementById('zoom').value"), "1.5");
    EXPECT_FALSE(browser.evaluate("location.hash.includes('zoom')").get<bool>());
    // Another choice: the projectors stay out.
    browser.evaluate("document.querySelector('#leave-out input[value=ticks]').click()");
    ASSERT_TRUE(browser.waitFor("location.hash.includes('hide=projectors%2Cticks')")) << browser.evaluate("location.hash");
    EXPECT_EQ(browser.evaluate("window.viewpipe.primitives()").get<long>(), all - projectors);
    // Both taken back: the projectors drawn, and the link says nothing is left out, opened anew too.
    for (const char* name : {"projectors", "ticks"})
        browser.evaluate(std::string("document.querySelector('#leave-out input[value=") + name + "]').click()");
    ASSERT_TRUE(browser.waitFor("window.viewpipe.primitives() === " + std::to_string(all)));
    const std::string link = browser.evaluate("location.href");
    browser.page("Page.navigate", {{"url", "about:blank"}});
    browser.page("Page.navigate", {{"url", link}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1' && document.body.dataset.core === '1' && "
                                "window.viewpipe.primitives() === " + std::to_string(all)));
    EXPECT_EQ(browser.evaluate(checked), "");
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// The zoom (the field, as export --zoom) is about the subject: about the focal point the core framed it on, where
// the text leaves it room, not about the view's center. Every point's picture moves away from that one point
// twice as far at twice the zoom.
TEST_F(WebPage, ZoomsAboutTheSubject)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-zoom");
    ASSERT_TRUE(browser.openWithCore("file://" + page.string() + "#stage=3"));
    const auto pixels = [&] {
        return json::parse(browser.evaluate("JSON.stringify([[0, 0, 54], [16, 10, 30], [8, 16, 54]].map((p) => window.viewpipe.pixelOf(p)))")
                               .get<std::string>());
    };
    const json before = pixels();
    browser.evaluate("document.getElementById('drawn').open = true");
    browser.evaluate("(z => { z.value = '2'; z.dispatchEvent(new Event('change')); })(document.getElementById('zoom'))");
    ASSERT_TRUE(browser.waitFor("location.hash.includes('zoom=2.000')"));
    const json after = pixels();
    // The point a zoom of 2 keeps: f = 2 a - a', the same for every point.
    std::vector<std::array<double, 2>> fixed;
    for (std::size_t k = 0; k < before.size(); ++k)
        fixed.push_back({2 * before[k]["x"].get<double>() - after[k]["x"].get<double>(),
                         2 * before[k]["y"].get<double>() - after[k]["y"].get<double>()});
    for (std::size_t k = 1; k < fixed.size(); ++k)
        for (int c = 0; c < 2; ++c)
            EXPECT_NEAR(fixed[k][std::size_t(c)], fixed[0][std::size_t(c)], 1.0) << "point " << k;
    // Not the view's center: the legend and caption take its left, the subject is framed right of them.
    const json view = json::parse(browser.evaluate("JSON.stringify((r => [(r.left + r.right) / 2, (r.top + r.bottom) / 2])"
                                                   "(document.getElementById('world').getBoundingClientRect()))").get<std::string>());
    EXPECT_GT(std::hypot(fixed[0][0] - view[0].get<double>(), fixed[0][1] - view[1].get<double>()), 20.0)
        << fixed[0][0] << ", " << fixed[0][1] << " against the view's center " << view;
    EXPECT_EQ(browser.evaluate("document.getElementById('zoom').value"), "2");
    browser.press("-", 189);
    ASSERT_TRUE(browser.waitFor("document.getElementById('zoom').value === '1.6'"));
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// Whether a point is drawn, in front of the eye: the page judges it by the core's rule (inFrontOfEye, its reach from
// the page's data), at the rule's edge too. Hand-checked: with x = 1 the least w drawn is 1 / kDrawnReach = 1e-9.
TEST_F(WebPage, JudgesInFrontOfTheEyeAsTheCoreDoes)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-in-front");
    browser.page("Page.navigate", {{"url", "file://" + page.string()}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.ready === '1'"));
    const struct {
        std::array<double, 4> h; // x, y, z, w
        bool inFront;
    } cases[] = {{{1, 0, 0, 1e-9 * (1 + 1e-6)}, true},  {{1, 0, 0, 1e-9 * (1 - 1e-6)}, false},
                 {{0, -1, 0, 1.000001e-9}, true},       {{1, 0, 0, 1e-12}, false},
                 {{2, 3, -4, 1}, true},                 {{2, 3, -4, -1}, false},
                 {{0, 0, 0, 0}, false},                 {{0, 0, 5e8, 0.5}, false}}; // at the reach itself: not drawn
    for (const auto& c : cases) {
        const std::string point = json(c.h).dump();
        const bool page = browser.evaluate("window.viewpipe.inFrontOfEye(" + point + ")").get<bool>();
        EXPECT_EQ(viewpipe::inFrontOfEye(viewpipe::Vec4<double>(c.h[0], c.h[1], c.h[2], c.h[3])), c.inFront) << point;
        EXPECT_EQ(page, c.inFront) << point;
    }
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// The view turned and zoomed by the reader is the core's turnedCamera, fitted to the view: a point's pixel on the page
// is where the core's matrices put it, for several turns.
TEST_F(WebPage, TurnsTheViewAsTheCoreTurnsIt)
{
    const fs::path page = *dir_ / "house" / "scene.html";
    Browser browser(*dir_ / "profile-turned");
    ASSERT_TRUE(browser.openWithCore("file://" + page.string() + "#stage=3"));
    const auto matrix = [](const json& rows) {
        viewpipe::Mat4<double> m;
        for (int k = 0; k < 16; ++k)
            m(k / 4, k % 4) = rows[std::size_t(k)].get<double>();
        return m;
    };
    const json frame = json::parse(browser.evaluate("JSON.stringify(window.viewpipe.frame())").get<std::string>());
    const json view = json::parse(browser.evaluate("JSON.stringify(document.getElementById('world-canvas')"
                                                   ".parentElement.getBoundingClientRect())").get<std::string>());
    const double width = std::round(view["width"].get<double>()), height = std::round(view["height"].get<double>());
    const double s = std::min(width / kWidth, height / kHeight); // the export's picture fitted whole
    viewpipe::Mat4<double> fit = viewpipe::Mat4<double>::Identity();
    fit(0, 0) = kWidth * s / width;
    fit(1, 1) = kHeight * s / height;
    const struct {
        double yaw, pitch, zoom;
    } turns[] = {{20, -10, 1.5}, {-120, 60, 0.7}, {0, 0, 1}, {175, 89, 3}};
    const std::vector<viewpipe::Vec3<double>> points = {viewpipe::Vec3<double>(0, 0, 54), viewpipe::Vec3<double>(16, 10, 30),
                                                        viewpipe::Vec3<double>(8, 16, 54)};
    for (const auto& turn : turns) {
        std::ostringstream fragment;
        fragment << "#stage=3&yaw=" << turn.yaw << "&pitch=" << turn.pitch << "&zoom=" << turn.zoom;
        browser.evaluate("location.hash = '" + fragment.str() + "&read'");
        ASSERT_TRUE(browser.waitFor("!location.hash.includes('read')")); // the page writes its link anew once read
        const viewpipe::report::TurnedCamera turned =
            viewpipe::report::turnedCamera(matrix(frame["view"]), matrix(frame["projection"]),
                                           viewpipe::Vec3<double>(frame["focal"][0], frame["focal"][1], frame["focal"][2]), turn.yaw, turn.pitch, turn.zoom);
        const viewpipe::Mat4<double> drawn = fit * turned.projection * turned.view * matrix(frame["shown"]);
        for (const viewpipe::Vec3<double>& p : points) {
            const viewpipe::Vec4<double> h = drawn * p.homogeneous();
            const json pixel = json::parse(browser.evaluate("JSON.stringify(window.viewpipe.pixelOf([" + std::to_string(p.x()) + ", " +
                                                            std::to_string(p.y()) + ", " + std::to_string(p.z()) + "]))")
                                               .get<std::string>());
            ASSERT_TRUE(pixel.is_object()) << fragment.str() << " " << p.transpose();
            EXPECT_NEAR(pixel["x"].get<double>() - view["left"].get<double>(), (h.x() / h.w() + 1) / 2 * width, 1e-6)
                << fragment.str() << " " << p.transpose();
            EXPECT_NEAR(pixel["y"].get<double>() - view["top"].get<double>(), (1 - h.y() / h.w()) / 2 * height, 1e-6)
                << fragment.str() << " " << p.transpose();
        }
    }
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// In every stage at once, a click in a cell traces the vertex it picks (the core's pickVertex, as in the world view
// and the app): every cell's footer gives its coordinates in that stage's space. What is shown is what is saved:
// the storyboard as PNG (the room's size) and as SVG (a group a cell, the core's shapes and texts).
TEST_F(WebPage, AClickInTheStoryboardTracesInEveryCellAndTheStoryboardIsSaved)
{
    const fs::path folder = *dir_ / "house";
    Browser browser(*dir_ / "profile-storyboard-trace", 1280, 720);
    browser.page("Page.navigate", {{"url", "file://" + (folder / "scene.html").string() + "#layout=storyboard"}});
    ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1' && document.querySelectorAll('#storyboard .cell').length === 6"));
    const auto footer = [&](int k) {
        return browser.evaluate("document.querySelector(`.cell[data-stage='" + std::to_string(k) + "'] .footer`).textContent")
            .get<std::string>();
    };
    ASSERT_EQ(footer(0), "traced (0, 0, 54)");
    // The house's top corner at the back, (8, 16, 30), clicked where stage 4's cell draws it; T(-PRP) takes it to (0, 10, -54).
    ASSERT_TRUE(clickOn(browser, "[8, 16, 30], 4"));
    ASSERT_TRUE(browser.waitFor("document.querySelector(`.cell[data-stage='0'] .footer`).textContent.includes('16')"));
    EXPECT_EQ(footer(0), "traced (8, 16, 30)");
    EXPECT_EQ(footer(3), "traced (0, 10, \u221254)");
    EXPECT_NE(browser.evaluate("document.getElementById('trace').textContent").get<std::string>().find("16"), std::string::npos)
        << "the trace table has it too";

    // Saved as shown: the buttons say so, the files are the storyboard's.
    EXPECT_EQ(browser.evaluate("document.getElementById('save-svg').textContent"), "Storyboard as SVG");
    browser.call("Browser.setDownloadBehavior", {{"behavior", "allow"}, {"downloadPath", folder.string()}});
    browser.evaluate("document.getElementById('save-png').click()");
    ASSERT_TRUE(waitForFile(folder / "foley-s-house-storyboard.png")) << "the storyboard's PNG is downloaded";
    const QImage png(QString::fromStdString((folder / "foley-s-house-storyboard.png").string()));
    const json room = json::parse(browser.evaluate("JSON.stringify((r => [Math.floor(r.width), Math.floor(r.height)])"
                                                   "(document.getElementById('storyboard').getBoundingClientRect()))").get<std::string>());
    EXPECT_EQ(png.width(), room[0].get<int>());
    EXPECT_EQ(png.height(), room[1].get<int>());
    // Each cell's picture where the page shows it.
    const json cell = json::parse(browser.evaluate("JSON.stringify((s => (r => [r.left - s.left, r.top - s.top, r.width, r.height])"
                                                   "(document.querySelector(`.cell[data-stage='5'] canvas`).getBoundingClientRect()))"
                                                   "(document.getElementById('storyboard').getBoundingClientRect()))").get<std::string>());
    const std::vector<bool> ink = drawn(png.copy(cell[0].get<int>(), cell[1].get<int>(), cell[2].get<int>(), cell[3].get<int>()));
    EXPECT_GT(std::count(ink.begin(), ink.end(), true), 500) << "stage 5's cell is in the PNG";
    browser.evaluate("document.getElementById('save-svg').click()");
    ASSERT_TRUE(waitForFile(folder / "foley-s-house-storyboard.svg")) << "the storyboard's SVG is downloaded";
    EXPECT_FALSE(fs::exists(folder / "foley-s-house-stage-0.svg")) << "not the hidden world view";
    browser.page("Page.navigate", {{"url", "file://" + (folder / "foley-s-house-storyboard.svg").string()}});
    ASSERT_TRUE(browser.waitFor("document.readyState === 'complete'"));
    EXPECT_EQ(browser.evaluate("document.documentElement.localName + ' ' + !document.querySelector('parsererror')"), "svg true");
    EXPECT_EQ(browser.evaluate("document.querySelectorAll('svg > g').length"), 6);
    EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('svg > g')].every((g) => g.querySelectorAll('polygon, polyline').length > 5)"),
              true);
    const std::string texts = browser.evaluate("[...document.querySelectorAll('svg > text')].map((t) => t.textContent).join('')");
    EXPECT_NE(texts.find("traced (8, 16, 30)"), std::string::npos) << texts;
    for (const std::string& problem : browser.problems())
        ADD_FAILURE() << problem;
}

// `lesson export` of dir/lesson.json into dir/out, and its page opened in `browser`, ready.
::testing::AssertionResult openExportedLesson(const fs::path& dir, Browser& browser)
{
    const Finished run = viewpipe({"lesson", "export", QString::fromStdString((dir / "lesson.json").string()), "--out",
                                   QString::fromStdString((dir / "out").string()), "--quiet"});
    if (run.exitCode != 0)
        return ::testing::AssertionFailure() << run.output;
    browser.page("Page.navigate", {{"url", "file://" + (dir / "out" / "lesson.html").string()}});
    if (!browser.waitFor("document.body.dataset.ready === '1'"))
        return ::testing::AssertionFailure() << "the lesson page is not ready";
    return ::testing::AssertionSuccess();
}

// A vertex traced while a question waits fills no trace: at the last stage the core's table ends with its
// verdict, an inside question's answer (it was in the page, hidden only by the style of the panel).
TEST(LessonPage, AVertexTracedWhileAQuestionWaitsShowsNoTrace)
{
    const fs::path dir = fs::temp_directory_path() / ("viewpipe-web-waiting-trace-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream lesson(dir / "lesson.json");
        lesson << R"({"title": "Inside", "steps": [{"scene": ")" << kData << R"(/scenes/house.json", "stage": 5, "caption": "c",
            "question": {"kind": "inside", "prompt": "Is the front corner inside?", "point": [0, 0, 54]}}]})";
    }
    {
        Browser browser(dir / "profile");
        ASSERT_TRUE(openExportedLesson(dir, browser));
        ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1' && document.body.dataset.stage === '5'"));
        ASSERT_TRUE(clickOn(browser, "[0, 0, 54]"));
        ASSERT_TRUE(browser.waitFor("JSON.stringify(window.viewpipe.traced()) === '[0,0,54]'"));
        EXPECT_EQ(browser.evaluate("document.getElementById('trace').textContent"), "");
        // Answered: the trace and its verdict.
        browser.evaluate("document.querySelector('#question .show-answer').click()");
        ASSERT_TRUE(browser.waitFor("document.getElementById('trace').textContent.includes('inside the canonical volume')"));
        for (const std::string& problem : browser.problems())
            ADD_FAILURE() << problem;
    }
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}

TEST(LessonPage, QuestionsAreAnsweredCheckedAndRevealed)
{
    const fs::path dir = fs::temp_directory_path() / ("viewpipe-web-lesson-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream lesson(dir / "lesson.json");
        lesson << R"({"title": "Two questions",
          "steps": [
            {"scene": ")" << kData << R"(/scenes/house.json", "stage": 2, "caption": "After $R$ the VRC axes are the world's.",
             "question": {"kind": "where", "prompt": "Where is the PRP after $T(-\\mathit{PRP})$?",
                          "point": [8, 6, 84], "after": 3, "explanation": "It moves by $-\\mathit{PRP}$."}},
            {"scene": ")" << kData << R"(/scenes/house.json", "stage": 3, "caption": "The shear comes next.",
             "question": {"kind": "entry", "prompt": "Entry (1, 3) of $SH_{per}$?", "stage": 4, "row": 1, "column": 3},
             "hide": ["labels"]},
            {"scene": ")" << kData << R"(/scenes/house.json", "stage": 4, "caption": "The last scale.",
             "question": {"kind": "where", "prompt": "Where does $S_{per}$ take the PRP?", "point": [8, 6, 84], "after": 5}}]})";
    }
    {
        Browser browser(dir / "profile");
        ASSERT_TRUE(openExportedLesson(dir, browser));
        EXPECT_EQ(browser.evaluate("document.getElementById('step-title').textContent"), "Step 1 of 3");
        // Asking: the caption and the matrices that would give the answer away are not there at all.
        EXPECT_EQ(browser.evaluate("getComputedStyle(document.getElementById('matrices')).visibility"), "hidden");
        EXPECT_EQ(browser.evaluate("document.getElementById('step-caption').textContent"), "");
        EXPECT_EQ(browser.evaluate("document.getElementById('matrix').textContent"), "");
        EXPECT_EQ(browser.evaluate("document.getElementById('stage-list').children.length"), 0);

        // A wrong answer first (typed into the fields, Enter), then the page says what is right.
        const auto answer = [&](const std::vector<std::string>& values) {
            for (std::size_t k = 0; k < values.size(); ++k) {
                browser.evaluate("document.querySelectorAll('#question input[type=text]')[" + std::to_string(k) + "].focus()");
                browser.evaluate("document.activeElement.value = ''");
                browser.page("Input.insertText", {{"text", values[k]}});
            }
            browser.press("Enter", 13);
        };
        // Read to a screen reader while asking: the question, not the step's text (which may hold the answer).
        ASSERT_TRUE(browser.waitFor("document.body.dataset.core === '1'")) << "the core checks the answers";
        const std::string live = "document.getElementById('live').textContent";
        EXPECT_NE(browser.evaluate(live).get<std::string>().find("Question: Where is the PRP"), std::string::npos);
        EXPECT_EQ(browser.evaluate(live).get<std::string>().find("VRC axes"), std::string::npos) << browser.evaluate(live);
        // Two tries (the default): the first wrong answer says so, the answer kept back and the form open.
        answer({"8", "6", "84"});
        ASSERT_TRUE(browser.waitFor("document.querySelector('#question .feedback').textContent.startsWith('Not quite. Try again')"));
        EXPECT_EQ(browser.evaluate("document.querySelector('#question .feedback').textContent"),
                  "Not quite. Try again: one more try before the answer is shown.");
        EXPECT_EQ(browser.evaluate(live).get<std::string>().find("(0, 0, 0)"), std::string::npos);
        EXPECT_EQ(browser.evaluate("getComputedStyle(document.getElementById('matrices')).visibility"), "hidden");
        EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('#question input')].some(i => i.disabled)"), false);
        answer({"8", "6", "83"});
        ASSERT_TRUE(browser.waitFor("document.body.dataset.answered === '1'"));
        EXPECT_NE(browser.evaluate(live).get<std::string>().find("VRC axes"), std::string::npos) << "the step's text, once answered";
        EXPECT_EQ(browser.evaluate("document.querySelectorAll('#step-caption .katex').length"), 1);
        // The answer as the app and the handout state it, its math set by KaTeX (the annotation keeps the source).
        EXPECT_EQ(browser.evaluate("document.querySelector('#question .feedback').firstChild.textContent"),
                  "Not quite: the answer is ");
        EXPECT_EQ(browser.evaluate("document.querySelector('#question .feedback annotation').textContent"), "(0, 0, 0)");
        // Revealed: the explanation, the stage the question is about reached by its transition.
        EXPECT_EQ(browser.evaluate("getComputedStyle(document.getElementById('matrices')).visibility"), "visible");
        ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '3' && !document.body.dataset.moving"));
        // Once revealed, the form is closed.
        EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('#question input')].every(i => i.disabled)"), true);

        // The clicker's key to the next step; an exact fraction is an answer.
        browser.evaluate("document.activeElement.blur()");
        browser.press("PageDown", 34);
        ASSERT_TRUE(browser.waitFor("document.getElementById('step-title').textContent === 'Step 2 of 3'"));
        // A text that is no number is refused with the core's reason, and costs no try (the results say 1).
        answer({"2 +* 3"});
        ASSERT_TRUE(browser.waitFor("document.querySelector('#question .feedback').textContent.startsWith('entry: ')"));
        EXPECT_EQ(browser.evaluate("document.querySelector('#question .feedback').textContent"),
                  "entry: expected a number, sqrt(...) or ( at character 4 of \"2 +* 3\".");
        answer({"-2/21"});
        ASSERT_TRUE(browser.waitFor("document.querySelector('#question .feedback').textContent === 'Right.'"));
        ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '4' && !document.body.dataset.moving"));
        const std::string hash = browser.evaluate("location.hash");
        EXPECT_NE(hash.find("step=2"), std::string::npos);

        // Step 3, predicted aloud: Show Answer closes it without an answer.
        browser.evaluate("document.activeElement.blur()");
        browser.press("PageDown", 34);
        ASSERT_TRUE(browser.waitFor("document.getElementById('step-title').textContent === 'Step 3 of 3'"));
        EXPECT_EQ(browser.evaluate("document.body.classList.contains('asking')"), true);
        browser.evaluate("document.querySelector('#question .show-answer').click()");
        ASSERT_TRUE(browser.waitFor("document.body.dataset.answered === '3'"));
        EXPECT_EQ(browser.evaluate("document.querySelector('#question .feedback').firstChild.textContent"), "The answer is ");
        EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('#question input, #question button')].every(i => i.disabled)"), true);

        // Saved: the results file as the app writes it, each typed answer beside its value, step 3 as revealed.
        browser.call("Browser.setDownloadBehavior", {{"behavior", "allow"}, {"downloadPath", dir.string()}});
        browser.evaluate("document.getElementById('save').click()");
        ASSERT_TRUE(waitForFile(dir / "lesson-results.json")) << "the results are downloaded";
        std::ifstream saved(dir / "lesson-results.json");
        const json results = json::parse(saved);
        EXPECT_EQ(results["lesson"], "Two questions");
        ASSERT_EQ(results["answers"].size(), 3u) << results.dump();
        EXPECT_EQ(results["answers"][0], json::parse(R"({"step": 1, "kind": "where", "answer": [8, 6, 83],
                                                        "typed": ["8", "6", "83"], "correct": false, "tries": 2})"));
        EXPECT_EQ(results["answers"][1], json::parse(R"({"step": 2, "kind": "entry", "answer": -0.09523809523809523,
                                                        "typed": "-2/21", "correct": true, "tries": 1})"));
        EXPECT_EQ(results["answers"][2], json::parse(R"({"step": 3, "kind": "where", "answer": null, "correct": false,
                                                        "revealed": true})"));

        // Back at step 1: its question stays closed, at the stage it is about, and cannot be answered again.
        browser.evaluate("document.activeElement.blur()");
        browser.press("Home", 36);
        ASSERT_TRUE(browser.waitFor("document.getElementById('step-title').textContent === 'Step 1 of 3'"));
        ASSERT_TRUE(browser.waitFor("document.body.dataset.stage === '3' && !document.body.dataset.moving"));
        EXPECT_EQ(browser.evaluate("document.querySelector('#question .feedback').firstChild.textContent"),
                  "Not quite: the answer is ");
        EXPECT_EQ(browser.evaluate("[...document.querySelectorAll('#question input, #question button')].every(i => i.disabled)"), true);
        EXPECT_EQ(browser.evaluate("document.body.classList.contains('asking')"), false);
        EXPECT_NE(browser.evaluate(live).get<std::string>().find("VRC axes"), std::string::npos);
        EXPECT_EQ(hash.find("stage="), std::string::npos) << "the stage would name which_stage answers";

        // Turned by the student, the labels are placed by the core as the step shows its scene: step 1 with the
        // set-up's names, step 2, which hides the scene's labels, without them (the axes keep their numbers).
        const auto namesTurned = [&] {
            const json labels = json::parse(browser.evaluate("JSON.stringify(window.viewpipe.turnedLabels())").get<std::string>());
            std::set<std::string> names;
            for (const json& label : labels)
                if (const std::string text = label["text"]; text == "PRP" || text == "VRP" || text == "CW" || text == "DOP")
                    names.insert(text);
            return std::make_pair(labels.is_array(), names);
        };
        browser.press("ArrowRight", 39, 8); // Shift: orbit
        const auto [placed1, names1] = namesTurned();
        EXPECT_TRUE(placed1) << "placed by the core";
        EXPECT_FALSE(names1.empty());
        browser.press("PageDown", 34);
        ASSERT_TRUE(browser.waitFor("document.getElementById('step-title').textContent === 'Step 2 of 3'"));
        ASSERT_TRUE(browser.waitFor("!document.body.dataset.moving"));
        browser.press("ArrowRight", 39, 8);
        const auto [placed2, names2] = namesTurned();
        EXPECT_TRUE(placed2);
        EXPECT_TRUE(names2.empty()) << *names2.begin();
        for (const std::string& problem : browser.problems())
            ADD_FAILURE() << problem;
    } // the browser ends before its profile is removed
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}

// What shows an answer: a number cut (not rounded) to 4 significant digits, its sign dropped; nothing
// for a whole number or one of fewer digits, which the page's other numbers would show by chance.
std::optional<std::string> cutNumber(double value)
{
    std::ostringstream fixed;
    fixed << std::fixed << std::setprecision(12) << std::abs(value);
    std::string text = fixed.str();
    text.erase(text.find_last_not_of('0') + 1); // "2." for 2, "0.5" for 0.5
    std::size_t digits = 0, at = 0;
    for (; at < text.size() && digits < 4; ++at)
        digits += std::isdigit(static_cast<unsigned char>(text[at])) && (digits > 0 || text[at] != '0');
    if (text.back() == '.' || digits < 4)
        return std::nullopt;
    return text.substr(0, at);
}

// The texts that would show a question's answer, in order, as the test reads them; none where nothing can
// be told from the page's other numbers (a point of whole numbers, 0.5).
std::vector<std::string> answerShown(const viewpipe::Question& q)
{
    std::vector<std::string> texts;
    switch (q.kind) {
    case viewpipe::QuestionKind::Where:
        for (int k = 0; k < 3; ++k)
            if (const auto cut = cutNumber(q.where[k]))
                texts.push_back(*cut);
        break;
    case viewpipe::QuestionKind::Entry:
        if (const auto cut = cutNumber(q.entry))
            texts.push_back(*cut);
        break;
    case viewpipe::QuestionKind::Inside:
        texts.push_back(q.inside ? "inside the canonical volume" : "outside the canonical volume");
        break;
    default: break;
    }
    return texts;
}

// The page's text as a person or a screen reader meets it, one entry a text node or an element of one line
// (a table row), and every aria-label and aria-description; never a script's (its data, sealed, holds the answers).
std::vector<std::string> pageTexts(Browser& browser)
{
    return json::parse(browser.evaluate(R"(JSON.stringify((() => {
        const texts = [];
        const outside = (node) => !node.parentElement || !node.parentElement.closest('script, style');
        const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
        for (let node; (node = walker.nextNode());) if (outside(node)) texts.push(node.data);
        for (const element of document.body.querySelectorAll('*')) {
          if (element.closest('script, style')) continue;
          const inner = element.innerText;
          if (inner && !inner.includes('\n')) texts.push(inner);
          for (const name of ['aria-label', 'aria-description'])
            if (element.hasAttribute(name)) texts.push(element.getAttribute(name));
        }
        return texts;
      })()))").get<std::string>());
}

// Whether one of the texts holds all of `shown`, in order.
bool holds(const std::vector<std::string>& texts, const std::vector<std::string>& shown)
{
    return !shown.empty() && std::any_of(texts.begin(), texts.end(), [&](const std::string& text) {
        std::size_t at = 0;
        for (const std::string& part : shown) {
            at = text.find(part, at);
            if (at == std::string::npos)
                return false;
            at += part.size();
        }
        return true;
    });
}

// Every built-in lesson, step by step in its page: before a step's question is answered nothing on the page
// shows that answer or a later question's; once it is shown (Show Answer), no later one's. Its source holds
// no caption, explanation or answer as text (a student found them all with View Source).
// A which_stage question shows its matrix as the core writes it, exactly where it reads so: the house from its
// corner (VPN (1, 0, 1), VUP the y axis) has R's rows u = (1, 0, -1)/sqrt(2), v = (0, 1, 0), n = (1, 0, 1)/sqrt(2).
TEST(LessonPage, AWhichStageMatrixIsTheCoresExactOne)
{
    const fs::path dir = fs::temp_directory_path() / ("viewpipe-web-which-stage-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream lesson(dir / "lesson.json");
        lesson << R"({"title": "Which stage", "steps": [{"scene": ")" << kData << R"(/scenes/house-corner.json",
            "stage": 1, "caption": "c", "question": {"kind": "which_stage", "prompt": "Which stage is this?", "stage": 2}}]})";
    }
    {
        Browser browser(dir / "profile");
        ASSERT_TRUE(openExportedLesson(dir, browser));
        EXPECT_EQ(browser.evaluate("document.querySelector('#question form .katex annotation').textContent"),
                  "\\begin{bmatrix}\n"
                  "  \\frac{\\sqrt{2}}{2} & 0 & -\\frac{\\sqrt{2}}{2} & 0 \\\\\n"
                  "  0 & 1 & 0 & 0 \\\\\n"
                  "  \\frac{\\sqrt{2}}{2} & 0 & \\frac{\\sqrt{2}}{2} & 0 \\\\\n"
                  "  0 & 0 & 0 & 1\n"
                  "\\end{bmatrix}");
        for (const std::string& problem : browser.problems())
            ADD_FAILURE() << problem;
    }
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}

TEST(LessonPage, NoAnswerIsOnThePageBeforeItsQuestionIsClosed)
{
    const fs::path dir = fs::temp_directory_path() / ("viewpipe-web-lessons-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    int told = 0; // questions whose answer the page could show, checked
    bool ownAnswerFound = false;
    for (const auto& file : fs::directory_iterator(kData + "/lessons")) {
        const std::string name = file.path().stem().string();
        SCOPED_TRACE(name);
        const viewpipe::Lesson lesson = viewpipe::loadLesson(file.path());
        const Finished run = viewpipe({"lesson", "export", QString::fromStdString(file.path().string()), "--out",
                                       QString::fromStdString((dir / name).string()), "--format", "html", "--quiet"});
        ASSERT_EQ(run.exitCode, 0) << run.output;
        // Nor in its source, which a student may read (View Source) or search: no caption, explanation or answer.
        {
            std::ifstream file(dir / name / "lesson.html");
            const std::string source((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
            int searched = 0;
            const auto expectNotIn = [&](const std::string& text, const std::string& what, std::size_t shortest = 8) {
                if (text.size() < shortest) // too short to be the step's own
                    return;
                const std::string escaped = json(text).dump();
                EXPECT_EQ(source.find(escaped.substr(1, escaped.size() - 2)), std::string::npos) << what << ": " << text;
                ++searched;
            };
            for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
                const viewpipe::LessonStep& step = lesson.steps[k];
                expectNotIn(step.caption, "step " + std::to_string(k + 1) + "'s caption");
                if (step.question) {
                    expectNotIn(step.question->explanation, "step " + std::to_string(k + 1) + "'s explanation");
                    for (const std::string& answer : answerShown(*step.question))
                        expectNotIn(answer, "step " + std::to_string(k + 1) + "'s answer", 4); // a number cut to 4 digits
                }
            }
            EXPECT_GE(searched, 3);
        }
        Browser browser(dir / (name + "-profile"));
        ASSERT_TRUE(browser.openWithCore("file://" + (dir / name / "lesson.html").string()));
        const int steps = int(lesson.steps.size());
        std::vector<std::vector<std::string>> answers(lesson.steps.size());
        for (int k = 0; k < steps; ++k)
            if (lesson.steps[std::size_t(k)].question)
                answers[std::size_t(k)] = answerShown(*lesson.steps[std::size_t(k)].question);
        told += int(std::count_if(answers.begin(), answers.end(), [](const auto& a) { return !a.empty(); }));
        // Nothing from `from` on shows, its question's answer and every later one. An inside question's answer
        // is the trace's verdict on its point, given away while that point is traced (as lesson_trust_test counts
        // it in the app, whose Matrices panel writes the same verdict).
        const auto expectNoneFrom = [&](int from, int at, const char* when) {
            const std::vector<std::string> texts = pageTexts(browser);
            const json traced = json::parse(browser.evaluate("JSON.stringify(window.viewpipe.traced())").get<std::string>());
            for (int j = from; j < steps; ++j) {
                const std::optional<viewpipe::Question>& q = lesson.steps[std::size_t(j)].question;
                if (q && q->kind == viewpipe::QuestionKind::Inside && traced != json{q->point.x(), q->point.y(), q->point.z()})
                    continue;
                EXPECT_FALSE(holds(texts, answers[std::size_t(j)]))
                    << "step " << at + 1 << " " << when << " shows step " << j + 1 << "'s answer " << json(answers[std::size_t(j)]);
            }
        };
        int closed = 0;
        for (int k = 0; k < steps; ++k) {
            const viewpipe::LessonStep& step = lesson.steps[std::size_t(k)];
            const std::string title = "Step " + std::to_string(k + 1) + " of " + std::to_string(steps);
            if (k > 0) {
                browser.evaluate("document.activeElement.blur()");
                browser.press("PageDown", 34);
            }
            ASSERT_TRUE(browser.waitFor("document.getElementById('step-title').textContent === '" + title +
                                        "' && document.body.dataset.stage === '" + std::to_string(step.question ? viewpipe::askingStage(step) : viewpipe::revealedStage(step)) +
                                        "' && !document.body.dataset.moving")) << title;
            expectNoneFrom(step.question ? k : k + 1, k, "while asking");
            if (!step.question)
                continue;
            browser.evaluate("document.querySelector('#question .show-answer').click()");
            ASSERT_TRUE(browser.waitFor("document.body.dataset.answered === '" + std::to_string(++closed) +
                                        "' && document.body.dataset.stage === '" + std::to_string(viewpipe::revealedStage(step)) +
                                        "' && !document.body.dataset.moving")) << title;
            expectNoneFrom(k + 1, k, "answered");
            // The check finds an answer that is shown: foley-nper's step 7, once revealed, traces its point there.
            if (name == "foley-nper" && k == 6) {
                ASSERT_FALSE(answers[6].empty());
                ownAnswerFound = holds(pageTexts(browser), answers[6]);
            }
        }
        for (const std::string& problem : browser.problems())
            ADD_FAILURE() << problem;
    }
    EXPECT_TRUE(ownAnswerFound) << "foley-nper's step 7 answer, revealed, is on the page";
    EXPECT_GE(told, 10) << "questions whose answers the page could give away";
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}

TEST(WebPageSize, AHundredThousandTriangleMeshStaysUnderTenMegabytes)
{
    const fs::path dir = fs::temp_directory_path() / ("viewpipe-web-mesh-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        // A 224 x 224 grid of squares, two triangles each: 100352 triangles, a hill 40 units across.
        std::ofstream obj(dir / "hill.obj");
        const int n = 224;
        for (int y = 0; y <= n; ++y)
            for (int x = 0; x <= n; ++x) {
                const double u = 40.0 * x / n - 20, v = 40.0 * y / n - 20;
                obj << "v " << u << " " << 10 * std::exp(-(u * u + v * v) / 100) << " " << v << "\n";
            }
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const int a = y * (n + 1) + x + 1, b = a + 1, c = a + n + 1, d = c + 1;
                obj << "f " << a << " " << c << " " << b << "\nf " << b << " " << c << " " << d << "\n";
            }
        std::ofstream scene(dir / "hill.json");
        scene << R"({"name": "A hill of 100352 triangles",
                     "camera": {"look_at": {"eye": [30, 40, 60], "center": [0, 0, 0], "up": [0, 1, 0]},
                                "projection": {"type": "perspective", "fovy_deg": 50, "aspect": 1.5, "near": 10, "far": 200}},
                     "objects": [{"type": "mesh", "path": "hill.obj"}]})";
    }
    const Finished run = viewpipe({"export", QString::fromStdString((dir / "hill.json").string()), "--out",
                                   QString::fromStdString((dir / "out").string()), "--format", "html", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::uintmax_t bytes = fs::file_size(dir / "out" / "scene.html");
    std::cout << "page of the 100352-triangle mesh: " << bytes << " bytes\n";
    EXPECT_LE(bytes, 10u << 20);
    // Its OBJ (over 3 MB) stays out of the page, and the JSON view says so.
    std::ifstream in(dir / "out" / "scene.html");
    std::stringstream text;
    text << in.rdbuf();
    const std::size_t note = text.str().find("The scene's meshes (");
    ASSERT_NE(note, std::string::npos);
    const std::size_t reason = text.str().find(" MB) are left out of this page", note);
    EXPECT_LE(reason - note, 24u) << "the note names the meshes' size in megabytes";
    fs::remove_all(dir);
}

} // namespace
