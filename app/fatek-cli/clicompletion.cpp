#include "clicompletion.h"

#include "clicommands.h"
#include "clioptions.h"
#include "core/watch/valueformat.h"

#include <QStringList>

namespace Fatek {

namespace {

QString formats()
{
    QStringList names;
    for (const DisplayFormat f : ValueFormat::allFormats())
        names << ValueFormat::name(f);
    return names.join(QLatin1Char(' '));
}

QString dashed(const QStringList &names)
{
    QStringList out;
    for (const QString &name : names)
        out << QStringLiteral("--") + name;
    return out.join(QLatin1Char(' '));
}

// The commands whose arguments are files (checkout: its plan, a CSV or a checkout file).
const char *const fileCommands
    = "backup restore snapshot diff restore-values alarms history checkout";

// The valued options of the runner's parser and those alarms parses itself (clialarms.cpp).
QStringList completedValuedNames()
{
    return valuedOptionNames()
           + QStringList{QStringLiteral("journal"), QStringLiteral("since"),
                         QStringLiteral("until"), QStringLiteral("connection")};
}

// Prints "@NAME" for every line NAME = URL of the named links file (app/common/namedlinks.h).
const char *const namedLinksShell
    = R"sh(sed -n 's/^[[:space:]]*\([^#=[:space:]]\{1,\}\)[[:space:]]*=.*/@\1/p' \
        "${FATEK_LINKS:-${XDG_CONFIG_HOME:-$HOME/.config}/fatek-studio/links.conf}" 2>/dev/null)sh";

QString bash()
{
    const QString valued
        = dashed(completedValuedNames()).replace(QLatin1Char(' '), QLatin1String(" | "));
    // The words are split at blanks only: bash's COMP_WORDBREAKS (with @ : =) would cut "@line1",
    // "tcp://host" and "--lang=en" apart. bash then replaces only the part of the word after its
    // last break character, so the replies lose what comes before it.
    return QStringLiteral(R"sh(# bash completion for fatek-cli (made by fatek-cli --completion bash)
_fatek_cli() {
    local line=${COMP_LINE:0:COMP_POINT} cur= prev= words=() i word command= broken=
    read -ra words <<<"$line"
    [[ $line =~ [[:space:]]$ ]] && words+=("")
    cur=${words[${#words[@]}-1]}
    ((${#words[@]} > 1)) && prev=${words[${#words[@]}-2]}
    if [[ $cur == --*=* ]]; then
        prev=${cur%%=*}
        cur=${cur#*=}
    fi
    COMPREPLY=()
    case $prev in
    --serial)
        COMPREPLY=($(compgen -W "$(ls -d /dev/ttyUSB* /dev/ttyACM* /dev/ttyS* /dev/serial/by-id/* 2>/dev/null)" -- "$cur")) ;;
    --link)
        COMPREPLY=($(compgen -W "$(%1) tcp:// udp:// serial://" -- "$cur"))
        compopt -o nospace 2>/dev/null ;;
    --protocol) COMPREPLY=($(compgen -W "facon binary auto" -- "$cur")) ;;
    --format) COMPREPLY=($(compgen -W "%2" -- "$cur")) ;;
    --parity) COMPREPLY=($(compgen -W "N E O" -- "$cur")) ;;
    --data) COMPREPLY=($(compgen -W "7 8" -- "$cur")) ;;
    --stop) COMPREPLY=($(compgen -W "1 2" -- "$cur")) ;;
    --completion) COMPREPLY=($(compgen -W "bash zsh" -- "$cur")) ;;
    --lang) COMPREPLY=($(compgen -W "en zh_TW" -- "$cur")) ;;
    --output | --names | --report | --punch | --save | --journal)
        COMPREPLY=($(compgen -f -- "$cur"))
        compopt -o filenames 2>/dev/null ;;
    %3) ;;
    *)
        if [[ $cur == -* ]]; then
            COMPREPLY=($(compgen -W "%4" -- "$cur"))
        else
            # The command of this step: the first word after the program or the last --then
            # that is neither an option nor an option's value.
            for ((i = 1; i < ${#words[@]} - 1; i++)); do
                word=${words[i]}
                case $word in
                --then) command= ;;
                --*=*) ;;
                %3) ((i++)) ;;
                -*) ;;
                *) [[ -z $command ]] && command=$word ;;
                esac
            done
            if [[ -z $command ]]; then
                COMPREPLY=($(compgen -W "%5" -- "$cur"))
            elif [[ " %6 " == *" $command "* ]]; then
                COMPREPLY=($(compgen -f -- "$cur"))
                compopt -o filenames 2>/dev/null
            fi
        fi ;;
    esac
    for ((i = ${#cur} - 1; i >= 0; i--)); do
        case ${cur:i:1} in
        [@\$]) broken=${cur:0:i} ;; # readline keeps these in the word it replaces
        *) [[ $COMP_WORDBREAKS == *"${cur:i:1}"* ]] && broken=${cur:0:i+1} ;;
        esac
        [[ -n $broken || $COMP_WORDBREAKS == *"${cur:i:1}"* ]] && break
    done
    [[ -n $broken ]] && COMPREPLY=("${COMPREPLY[@]#"$broken"}")
    return 0
}
complete -F _fatek_cli fatek-cli
)sh")
        .arg(QString::fromLatin1(namedLinksShell), formats(), valued,
             dashed(completedValuedNames() + flagOptionNames()),
             commandNames().join(QLatin1Char(' ')), QString::fromLatin1(fileCommands));
}

QString zsh()
{
    // _arguments specs: valued options with what their value is, then the flags.
    QStringList specs;
    auto valued = [&specs](const QString &name, const QString &action) {
        specs << QStringLiteral("'--%1=[]:%1:%2'").arg(name, action);
    };
    for (const QString &name : completedValuedNames()) {
        if (name == QLatin1String("serial"))
            valued(name, QStringLiteral("_files -g \"/dev/tty*(N) /dev/serial/by-id/*(N)\""));
        else if (name == QLatin1String("link"))
            valued(name, QStringLiteral("(tcp:// udp:// serial:// ${links})"));
        else if (name == QLatin1String("protocol"))
            valued(name, QStringLiteral("(facon binary auto)"));
        else if (name == QLatin1String("format"))
            valued(name, QStringLiteral("(%1)").arg(formats()));
        else if (name == QLatin1String("parity"))
            valued(name, QStringLiteral("(N E O)"));
        else if (name == QLatin1String("data"))
            valued(name, QStringLiteral("(7 8)"));
        else if (name == QLatin1String("stop"))
            valued(name, QStringLiteral("(1 2)"));
        else if (name == QLatin1String("completion"))
            valued(name, QStringLiteral("(bash zsh)"));
        else if (name == QLatin1String("lang"))
            valued(name, QStringLiteral("(en zh_TW)"));
        else if (name == QLatin1String("output") || name == QLatin1String("names")
                 || name == QLatin1String("journal") || name == QLatin1String("report")
                 || name == QLatin1String("save") || name == QLatin1String("punch"))
            valued(name, QStringLiteral("_files"));
        else
            valued(name, QStringLiteral(" "));
    }
    for (const QString &name : flagOptionNames())
        specs << QStringLiteral("'*--%1[]'").arg(name);
    return QStringLiteral(R"sh(#compdef fatek-cli
# zsh completion for fatek-cli (made by fatek-cli --completion zsh)
local -a links commands
links=(${(f)"$(%1)"})
commands=(%2)
_arguments -S \
  %3 \
  '*:: :->step'
if [[ $state == step ]]; then
  if (( CURRENT == 1 )) || [[ ${words[CURRENT-1]} == --then ]]; then
    _describe command commands
  elif [[ " %4 " == *" ${words[1]} "* ]]; then
    _files
  fi
fi
)sh")
        .arg(QString::fromLatin1(namedLinksShell), commandNames().join(QLatin1Char(' ')),
             specs.join(QStringLiteral(" \\\n  ")), QString::fromLatin1(fileCommands));
}

} // namespace

QString completionScript(const QString &shell)
{
    return shell == QLatin1String("zsh") ? zsh() : bash();
}

} // namespace Fatek
