<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
<context>
    <name>CommissionCli</name>
    <message>
        <source>usage: frezka-cli commission --port PATH [--machine PROFILE] [--baud N] --report FILE [--profile-out FILE]
</source>
        <translation>použití: frezka-cli commission --port CESTA [--machine PROFIL] [--baud N] --report SOUBOR [--profile-out SOUBOR]
</translation>
    </message>
    <message>
        <source>frezka-cli commission: bad option &apos;%1&apos;
</source>
        <translation>frezka-cli commission: chybná volba &apos;%1&apos;
</translation>
    </message>
    <message>
        <source>frezka-cli commission: --port and --report are needed
</source>
        <translation>frezka-cli commission: je třeba zadat --port a --report
</translation>
    </message>
    <message>
        <source>frezka-cli commission: cannot open %1: %2
</source>
        <translation>frezka-cli commission: nelze otevřít %1: %2
</translation>
    </message>
    <message>
        <source>Run this step? (y = run, n = skip)</source>
        <translation>Provést tento krok? (y = provést, n = přeskočit)</translation>
    </message>
    <message>
        <source>no terminal on standard input: nobody to confirm it; run frezka-cli commission in a terminal</source>
        <translation>na standardním vstupu není terminál: nikdo by krok nepotvrdil; spusťte frezka-cli commission v terminálu</translation>
    </message>
    <message>
        <source>the port could not be opened</source>
        <translation>port nelze otevřít</translation>
    </message>
    <message>
        <source>Skipped (they move or need the operator):
</source>
        <translation>Přeskočeno (pohybují strojem nebo potřebují obsluhu):
</translation>
    </message>
    <message>
        <source>Report written to %1
</source>
        <translation>Protokol zapsán do %1
</translation>
    </message>
    <message>
        <source>Updated profile written to %1
</source>
        <translation>Upravený profil zapsán do %1
</translation>
    </message>
</context>
<context>
    <name>ControllerHeader</name>
    <message>
        <source>The header &quot;%1&quot; holds &apos;%2&apos;, which the controller cannot show (it shows letters without diacritics, digits and signs). Replace it.</source>
        <translation>Hlavička „%1“ obsahuje &apos;%2&apos;, který řídicí systém nedokáže zobrazit (zobrazí písmena bez diakritiky, číslice a znaménka). Nahraďte ho.</translation>
    </message>
    <message>
        <source>The header &quot;%1&quot; is sent as &quot;%2&quot;: the controller has no Czech letters, so they become their base letters.</source>
        <translation>Hlavička „%1“ se pošle jako „%2“: řídicí systém nemá česká písmena, proto se mění na písmena bez diakritiky.</translation>
    </message>
</context>
<context>
    <name>EdgeCli</name>
    <message>
        <source>usage: frezka-cli probe corner --x-direction +|- --y-direction +|- --tool-diameter MM [--reach MM] [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>použití: frezka-cli probe corner --x-direction +|- --y-direction +|- --tool-diameter MM [--reach MM] [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port CESTA|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>usage: frezka-cli probe edge --axis x|y --direction +|- --tool-diameter MM [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>použití: frezka-cli probe edge --axis x|y --direction +|- --tool-diameter MM [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port CESTA|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>--tool-diameter %1: the diameter of the tool (or the probe&apos;s ball) must be 0 mm or more.</source>
        <translation>--tool-diameter %1: průměr nástroje (nebo kuličky sondy) musí být 0 mm nebo víc.</translation>
    </message>
    <message>
        <source>--travel %1: how far the probe may move toward the edge must be above 0 mm.</source>
        <translation>--travel %1: dráha, o kterou se sonda smí posunout k hraně, musí být větší než 0 mm.</translation>
    </message>
    <message>
        <source>--retract %1: the back-off before the slow probe must be above 0 mm.</source>
        <translation>--retract %1: odjetí před pomalým sondováním musí být větší než 0 mm.</translation>
    </message>
    <message>
        <source>--reach %1: the move beside an outside corner&apos;s face must be 0 mm (an inside corner) or more.</source>
        <translation>--reach %1: přejezd vedle stěny vnějšího rohu musí být 0 mm (vnitřní roh) nebo víc.</translation>
    </message>
    <message>
        <source>frezka-cli probe %1: %2
</source>
        <translation>frezka-cli probe %1: %2
</translation>
    </message>
    <message>
        <source>%1 is now X %2, Y %3 (machine mm of its zero): the %4 is the work&apos;s zero, with the tool&apos;s radius of %5 mm taken into account. Give the next commands --offset %6.
</source>
        <translation>%1 je nyní X %2, Y %3 (strojní mm své nuly): %4 je nulou obrobku, s ohledem na poloměr nástroje %5 mm. Dalším příkazům zadejte --offset %6.
</translation>
    </message>
    <message>
        <source>corner</source>
        <translation>roh</translation>
    </message>
    <message>
        <source>edge</source>
        <translation>hrana</translation>
    </message>
</context>
<context>
    <name>EmulatorTransport</name>
    <message>
        <source>built-in %1 emulator</source>
        <translation>vestavěný emulátor %1</translation>
    </message>
</context>
<context>
    <name>GrinderCli</name>
    <message>
        <source>--header: &apos;%1&apos; is longer than 16 characters</source>
        <translation>--header: &apos;%1&apos; má víc než 16 znaků</translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not a baud rate</source>
        <translation>--baud: &apos;%1&apos; není přenosová rychlost</translation>
    </message>
    <message>
        <source>--retries: &apos;%1&apos; is not 0 to 100</source>
        <translation>--retries: &apos;%1&apos; není v rozsahu 0 až 100</translation>
    </message>
    <message>
        <source>--reply-timeout-ms: &apos;%1&apos; is not 100 to 600000</source>
        <translation>--reply-timeout-ms: &apos;%1&apos; není v rozsahu 100 až 600000</translation>
    </message>
    <message>
        <source>--form: &apos;%1&apos; is not 1 or 2</source>
        <translation>--form: &apos;%1&apos; není 1 ani 2</translation>
    </message>
    <message>
        <source>unknown option &apos;%1&apos;</source>
        <translation>neznámá volba &apos;%1&apos;</translation>
    </message>
    <message>
        <source>frezka-cli grinder: unknown action &apos;%1&apos;
</source>
        <translation>frezka-cli grinder: neznámá akce &apos;%1&apos;
</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>nečekaný argument &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1 needs a value</source>
        <translation>%1 potřebuje hodnotu</translation>
    </message>
    <message>
        <source>--port PATH is required</source>
        <translation>je třeba zadat --port CESTA</translation>
    </message>
    <message>
        <source>%1 needs a FILE</source>
        <translation>%1 potřebuje SOUBOR</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 left</source>
        <translation>zbývá %1</translation>
    </message>
    <message>
        <source>frezka-cli grinder: %1 failed (%2): %3
</source>
        <translation>frezka-cli grinder: %1 selhalo (%2): %3
</translation>
    </message>
    <message>
        <source>Repeats: %1 (NAK %2, bad checksum %3), noise bytes skipped: %4
</source>
        <translation>Opakování: %1 (NAK %2, chybný kontrolní součet %3), přeskočené bajty šumu: %4
</translation>
    </message>
    <message>
        <source>Inner blocks: %1
</source>
        <translation>Vnitřní bloky: %1
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: cannot write %1: %2 (the data were received but not saved)
</source>
        <translation>frezka-cli grinder: nelze zapsat %1: %2 (data byla přijata, ale neuložena)
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: cannot read %1: %2
</source>
        <translation>frezka-cli grinder: nelze číst %1: %2
</translation>
    </message>
    <message>
        <source>Note: TCHIN programs show &quot;no prg set&quot; once until the X axis is set up: select the program in AUT and hold RES.
</source>
        <translation>Poznámka: programy TCHIN ukážou jednou „no prg set“, dokud se nenastaví osa X: zvolte program v AUT a podržte RES.
</translation>
    </message>
    <message>
        <source>Z = %1 mm
</source>
        <translation>Z = %1 mm
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: --go needs FORM=1; FORM=2 only reports
</source>
        <translation>frezka-cli grinder: --go vyžaduje FORM=1; FORM=2 polohu jen hlásí
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: no FORM=2 position frame within %1 s
</source>
        <translation>frezka-cli grinder: během %1 s nepřišel žádný rámec polohy FORM=2
</translation>
    </message>
    <message>
        <source>Moving to %1 mm...
</source>
        <translation>Přejíždím na %1 mm...
</translation>
    </message>
    <message>
        <source>--go: &apos;%1&apos; is not a position from -9999.999 to 9999.999 mm (e.g. 12.5)</source>
        <translation>--go: &apos;%1&apos; není poloha od -9999.999 do 9999.999 mm (např. 12.5)</translation>
    </message>
    <message>
        <source>frezka-cli grinder: cannot write %1: %2; nothing was asked from the controller
</source>
        <translation>frezka-cli grinder: nelze zapsat %1: %2; od řídicího systému se nic nežádalo
</translation>
    </message>
    <message>
        <source>--header: ANC messages carry no header (ANCLOAD sent none); leave it out or choose --family k51 or hedit</source>
        <translation>--header: zprávy ANC nemají hlavičku (ANCLOAD žádnou neposílal); vynechte ji, nebo zvolte --family k51 či hedit</translation>
    </message>
    <message>
        <source>frezka-cli grinder: %1 is damaged: %2; nothing was sent
</source>
        <translation>frezka-cli grinder: %1 je poškozený: %2; nic se neposlalo
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: %1 holds %2 data (saved from a %2 control), not %3: is the wrong system selected? Use --family %4.
</source>
        <translation>frezka-cli grinder: %1 obsahuje data %2 (uložená z řídicího systému %2), ne %3: není vybrán nesprávný systém? Použijte --family %4.
</translation>
    </message>
    <message>
        <source>usage: frezka-cli grinder ping|save|load --port PATH [--family k51|anc|hedit|table]
                          [--baud N] [--header TEXT] [--retries N]
                          [--reply-timeout-ms N] [--send-anyway] [--raw] FILE
       frezka-cli grinder z --port PATH [--baud N] [--form 1|2] [--go MM]
                          [--reply-timeout-ms N]
  ping   link check (ENQ/ACK)
  save   controller -&gt; PC: write the controller&apos;s data to FILE, byte for byte, with
         its header and system (a FILE ending in .bin, or --raw: the bare data, as
         the old tools wrote)
  load   PC -&gt; controller: send FILE unchanged; the 16-character header is --header
         or the one saved in FILE or, as K51LOAD 2.20 did, the file name (Czech
         letters become their base letters); the file&apos;s length and inner blocks
         are checked first and nothing is sent when they are wrong
         --family table sends an APROXTAB table (LOA1) to a K51 set to table
         transfer (KONFIG6 = 3); a table cannot be saved
  z      Z-position link: print the table position (FORM=1 asks with Z?, FORM=2
         waits for a binary frame); --go MM moves the table and waits until reached
  --baud N               line rate (default: ANC 4800 Bd, as ANCLOAD/ANCSAVE; K51 and
                         HEDIT 9600 Bd)
  --retries N            repeats after a timeout, NAK or bad checksum (default 3)
  --reply-timeout-ms N   silence allowed before a reply (default 3000; 10000 for
                         the data after a request)
  --send-anyway          load a file whose inner blocks have a wrong checksum (only
                         if the controller itself gave it to you)
  --go MM                -9999.999 to 9999.999 mm
  --help                 this text
Exit status: 0 done, 1 transfer failed (the reason is printed), 2 usage error.
</source>
        <translation>použití: frezka-cli grinder ping|save|load --port CESTA [--family k51|anc|hedit|table]
                          [--baud N] [--header TEXT] [--retries N]
                          [--reply-timeout-ms N] [--send-anyway] [--raw] SOUBOR
       frezka-cli grinder z --port CESTA [--baud N] [--form 1|2] [--go MM]
                          [--reply-timeout-ms N]
  ping   kontrola spojení (ENQ/ACK)
  save   řídicí systém -&gt; PC: zapíše data řídicího systému do SOUBORU, bajt po bajtu,
         s jejich hlavičkou a systémem (SOUBOR s příponou .bin nebo --raw: jen holá
         data, jak je zapisovaly staré programy)
  load   PC -&gt; řídicí systém: pošle SOUBOR beze změny; 16znakovou hlavičku dává --header,
         jinak hlavička uložená v SOUBORU, jinak (jako K51LOAD 2.20) název souboru
         (česká písmena se mění na písmena bez diakritiky); délka a vnitřní bloky
         souboru se nejprve zkontrolují a při chybě se nepošle nic
         --family table pošle tabulku APROXTAB (LOA1) do K51 nastaveného na přenos
         tabulky (KONFIG6 = 3); tabulku nelze uložit
  z      přenos polohy Z: vypíše polohu stolu (FORM=1 se ptá Z?, FORM=2
         čeká na binární rámec); --go MM přejede stolem a čeká na dosažení
  --baud N               rychlost linky (výchozí: ANC 4800 Bd jako ANCLOAD/ANCSAVE; K51
                         a HEDIT 9600 Bd)
  --retries N            opakování po vypršení času, NAK nebo chybném součtu (výchozí 3)
  --reply-timeout-ms N   povolené ticho před odpovědí (výchozí 3000; 10000 pro
                         data po žádosti)
  --send-anyway          pošle soubor, jehož vnitřní bloky mají chybný součet (jen
                         když ho dal sám řídicí systém)
  --go MM                -9999,999 až 9999,999 mm
  --help                 tento text
Návratový kód: 0 hotovo, 1 přenos selhal (důvod se vypíše), 2 chybné použití.
</translation>
    </message>
    <message>
        <source>--family: &apos;%1&apos; is not k51, anc, hedit or table</source>
        <translation>--family: &apos;%1&apos; není k51, anc, hedit ani table</translation>
    </message>
</context>
<context>
    <name>LinkWorker</name>
    <message>
        <source>connected: %1</source>
        <translation>připojeno: %1</translation>
    </message>
    <message>
        <source>no serial port given</source>
        <translation>není zadán sériový port</translation>
    </message>
    <message>
        <source>unknown connection kind</source>
        <translation>neznámý druh připojení</translation>
    </message>
    <message>
        <source>simulated handwheel: not connected to the built-in emulator; turn the unit&apos;s own MPG wheel</source>
        <translation>simulované kolečko: nepřipojeno k vestavěnému emulátoru; otočte skutečným kolečkem MPG jednotky</translation>
    </message>
    <message>
        <source>simulated handwheel: the unit ignored the turn; switch Handwheel (MPG) on, and enable the MPG in the profile&apos;s EEPROM settings</source>
        <translation>simulované kolečko: jednotka otočení nepřijala; zapněte Ruční kolečko (MPG) a povolte MPG v nastavení EEPROM profilu</translation>
    </message>
    <message>
        <source>another unit becomes the machine only while every unit on the line is idle; wait, or stop the units, then choose again</source>
        <translation>jiná jednotka se může stát strojem, jen když všechny jednotky na lince stojí; počkejte nebo jednotky zastavte a zvolte znovu</translation>
    </message>
    <message>
        <source>the units cannot share the built-in emulator&apos;s line: %1; fix line.units in the machine profile</source>
        <translation>jednotky nemohou sdílet linku vestavěného emulátoru: %1; opravte line.units v profilu stroje</translation>
    </message>
</context>
<context>
    <name>LoadCheck</name>
    <message>
        <source>ANC</source>
        <translation>ANC</translation>
    </message>
    <message>
        <source>K51</source>
        <translation>K51</translation>
    </message>
    <message>
        <source>HEDIT</source>
        <translation>HEDIT</translation>
    </message>
    <message>
        <source>ANC program data have 21760 or 21766 bytes (0x5500 or 0x5506)</source>
        <translation>Programová data ANC mají 21760 nebo 21766 bajtů (0x5500 nebo 0x5506)</translation>
    </message>
    <message>
        <source>K51 program data have 21767 bytes (0x5507)</source>
        <translation>Programová data K51 mají 21767 bajtů (0x5507)</translation>
    </message>
    <message>
        <source>HEDIT data have 46 bytes (0x2E)</source>
        <translation>Data HEDIT mají 46 bajtů (0x2E)</translation>
    </message>
    <message>
        <source>The file is empty; there is nothing to send.</source>
        <translation>Soubor je prázdný; není co poslat.</translation>
    </message>
    <message>
        <source>Sent anyway: %1 bytes, the length this controller reported.</source>
        <translation>Přesto odesláno: %1 bajtů, délka, kterou hlásil tento řídicí systém.</translation>
    </message>
    <message>
        <source>%1; the file has %2, so nothing was sent. Choose a file saved from this controller.</source>
        <translation>%1; soubor má %2, proto se nic neposlalo. Vyberte soubor uložený z tohoto řídicího systému.</translation>
    </message>
    <message>
        <source>%1; the file has %2, the length of %3 data: is the wrong system selected? Nothing was sent.</source>
        <translation>%1; soubor má %2, což je délka dat %3: není vybrán nesprávný systém? Nic se neposlalo.</translation>
    </message>
    <message>
        <source>This controller reported this length: choose &quot;Send anyway&quot; to send it.</source>
        <translation>Tuto délku hlásil tento řídicí systém: chcete-li soubor poslat, zvolte „Přesto odeslat“.</translation>
    </message>
    <message>
        <source>%1 of the %2 inner program blocks lack their AA and block number marker (%3): the file is not a program image of this system or it was changed. Nothing was sent.</source>
        <translation>%1 z %2 vnitřních programových bloků nemá značku AA a číslo bloku (%3): soubor není programový obraz tohoto systému nebo byl změněn. Nic se neposlalo.</translation>
    </message>
    <message>
        <source>inner blocks with a wrong checksum: %1</source>
        <translation>vnitřní bloky s chybným kontrolním součtem: %1</translation>
    </message>
    <message>
        <source>The file has %1. Nothing was sent. If the controller itself gave you this file, choose &quot;Send anyway&quot;: it gets the data unchanged.</source>
        <translation>Soubor má %1. Nic se neposlalo. Pokud vám tento soubor dal sám řídicí systém, zvolte „Přesto odeslat“: dostane data beze změny.</translation>
    </message>
    <message>
        <source>Sent anyway: %1.</source>
        <translation>Přesto odesláno: %1.</translation>
    </message>
</context>
<context>
    <name>ProbeCli</name>
    <message>
        <source>usage: frezka-cli probe z-plate --plate MM [--feed MM/MIN] [--slow-feed MM/MIN] [--depth MM] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>použití: frezka-cli probe z-plate --plate MM [--feed MM/MIN] [--slow-feed MM/MIN] [--depth MM] [--retract MM] [--port CESTA|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>--plate %1: the plate&apos;s thickness must be 0 mm or more (0: the tool touches the work itself).</source>
        <translation>--plate %1: tloušťka destičky musí být 0 mm nebo více (0: nástroj se dotkne přímo obrobku).</translation>
    </message>
    <message>
        <source>--depth %1: how far below the start the probe may go must be above 0 mm.</source>
        <translation>--depth %1: jak hluboko pod výchozí polohu smí sonda sjet, musí být víc než 0 mm.</translation>
    </message>
    <message>
        <source>--retract %1: the back-off above the plate must be above 0 mm.</source>
        <translation>--retract %1: odjetí nad destičku musí být víc než 0 mm.</translation>
    </message>
    <message>
        <source>--slow-feed %1: the slow probe&apos;s feed must be above 0 mm/min.</source>
        <translation>--slow-feed %1: posuv pomalého sondování musí být víc než 0 mm/min.</translation>
    </message>
    <message>
        <source>frezka-cli probe z-plate: %1
</source>
        <translation>frezka-cli probe z-plate: %1
</translation>
    </message>
    <message>
        <source>The plate&apos;s top touched at machine Z %1; %2 Z is now %3 (was %4), so the work&apos;s top under the %5 mm plate is Z 0 and the tool stands at Z %6. Give the next commands --offset %7.
</source>
        <translation>Sonda se dotkla horní plochy destičky ve strojovém Z %1; Z systému %2 je nyní %3 (bylo %4), takže horní plocha obrobku pod destičkou tlustou %5 mm je Z 0 a nástroj stojí v Z %6. Dalším příkazům zadejte --offset %7.
</translation>
    </message>
    <message>
        <source>usage: frezka-cli probe tool-length --tool N [--table FILE] [--port PATH|sim] [--surface SPEC] [--machine PROFILE]
</source>
        <translation>použití: frezka-cli probe tool-length --tool N [--table SOUBOR] [--port CESTA|sim] [--surface SPEC] [--machine PROFIL]
</translation>
    </message>
    <message>
        <source>frezka-cli probe tool-length: %1
</source>
        <translation>frezka-cli probe tool-length: %1
</translation>
    </message>
    <message>
        <source>Tool %1 is %2 mm long (tripped at machine Z %3). The profile names no tool table: set tools.tableFile to keep it, or apply it with G43.1 Z%2.
</source>
        <translation>Nástroj %1 je dlouhý %2 mm (sepnul ve strojní Z %3). Profil neuvádí tabulku nástrojů: nastavte tools.tableFile, aby se délka uložila, nebo ji použijte pomocí G43.1 Z%2.
</translation>
    </message>
    <message>
        <source>Tool %1 is %2 mm long (tripped at machine Z %3); written to %4.
</source>
        <translation>Nástroj %1 je dlouhý %2 mm (sepnul ve strojní Z %3); zapsáno do %4.
</translation>
    </message>
    <message>
        <source>frezka-cli probe: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0], warp:Z0,DZDX,DZDY,AMP,PERIOD or block:X0,Y0,X1,Y1,TOP (machine mm)
</source>
        <translation>frezka-cli probe: --surface %1: očekáváno plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0], warp:Z0,DZDX,DZDY,AMP,PERIOD nebo block:X0,Y0,X1,Y1,TOP (strojní mm)
</translation>
    </message>
</context>
<context>
    <name>ProbeFollow</name>
    <message>
        <source>%1: the probe move that ran does not end where the machine stopped when the program is interpreted again; it cannot go on from the probe&apos;s result.</source>
        <translation>%1: provedený pohyb sondy po nové interpretaci programu nekončí tam, kde se stroj zastavil; z výsledku sondy nelze pokračovat.</translation>
    </message>
    <message>
        <source>the program could not be interpreted again</source>
        <translation>program nelze znovu interpretovat</translation>
    </message>
    <message>
        <source>%1: the program runs %2 probe moves when interpreted with the results of those run so far, fewer than the %3 the machine has run; it cannot go on from the probe&apos;s result.</source>
        <translation>%1: program interpretovaný s výsledky dosud provedených sond provede %2 pohybů sondy, méně než %3, které stroj už provedl; z výsledku sondy nelze pokračovat.</translation>
    </message>
    <message>
        <source>the program could not be planned</source>
        <translation>program nelze naplánovat</translation>
    </message>
    <message>
        <source>Line %1: the program probes for itself: after line %2 its path depends on that probe&apos;s result, and the probes before line %1 would not run. Run the whole program.</source>
        <translation>Řádek %1: program sám sonduje: za řádkem %2 závisí jeho dráha na výsledku té sondy a sondy před řádkem %1 by neproběhly. Spusťte celý program.</translation>
    </message>
    <message>
        <source>Line %1: the program probes for itself (after this line its path depends on the probe&apos;s result): a height map cannot be applied to it. Remove the map to run the program.</source>
        <translation>Řádek %1: program sám sonduje (za tímto řádkem závisí jeho dráha na výsledku sondy): výškovou mapu na něj nelze použít. Pro spuštění programu mapu odeberte.</translation>
    </message>
</context>
<context>
    <name>ProbeGridCli</name>
    <message>
        <source>usage: frezka-cli probe-grid (--area X0,Y0,X1,Y1 | --program FILE) --spacing MM --clearance MM --depth MM --feed MM/MIN --out MAP.csv [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>použití: frezka-cli probe-grid (--area X0,Y0,X1,Y1 | --program SOUBOR) --spacing MM --clearance MM --depth MM --feed MM/MIN --out MAPA.csv [--port CESTA|sim] [--surface POPIS] %1
</translation>
    </message>
    <message>
        <source>frezka-cli probe-grid: --area %1: expected four numbers X0,Y0,X1,Y1 (mm), such as 0,0,80,60
</source>
        <translation>frezka-cli probe-grid: --area %1: očekávána čtyři čísla X0,Y0,X1,Y1 (mm), např. 0,0,80,60
</translation>
    </message>
    <message>
        <source>%1: the program cuts nothing (no feed move or arc): give the area with --area X0,Y0,X1,Y1
</source>
        <translation>%1: program nic neobrábí (žádný pracovní posuv ani oblouk): zadejte oblast pomocí --area X0,Y0,X1,Y1
</translation>
    </message>
    <message>
        <source>frezka-cli probe-grid: %1
</source>
        <translation>frezka-cli probe-grid: %1
</translation>
    </message>
    <message>
        <source>%1 points probed, heights %2 to %3 mm from the first point (machine Z %4); the map is in %5. Set the work&apos;s Z zero on the surface at the first point (X %6, Y %7) before running with --height-map.
</source>
        <translation>Nasondováno %1 bodů, výšky %2 až %3 mm vůči prvnímu bodu (Z stroje %4); mapa je v %5. Před spuštěním s --height-map nastavte nulu Z obrobku na povrch v prvním bodě (X %6, Y %7).
</translation>
    </message>
    <message>
        <source>frezka-cli probe-grid: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm)
</source>
        <translation>frezka-cli probe-grid: --surface %1: očekáváno plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] nebo warp:Z0,DZDX,DZDY,AMP,PERIOD (mm stroje)
</translation>
    </message>
</context>
<context>
    <name>ProbeRunCli</name>
    <message>
        <source>could not connect to the emulator</source>
        <translation>nelze se připojit k emulátoru</translation>
    </message>
    <message>
        <source>probing did not end within a day of the emulator&apos;s time</source>
        <translation>sondování neskončilo do jednoho dne času emulátoru</translation>
    </message>
</context>
<context>
    <name>ProgramCli</name>
    <message>
        <source>frezka-cli: %1 needs a value
</source>
        <translation>frezka-cli: %1 potřebuje hodnotu
</translation>
    </message>
    <message>
        <source>frezka-cli: %1 %2: expected %3 (machine mm of the program&apos;s zero)
</source>
        <translation>frezka-cli: %1 %2: očekáváno %3 (strojní mm nuly programu)
</translation>
    </message>
    <message>
        <source>Height map %1 applied: X %2 to %3, Y %4 to %5 mm, heights %6 to %7 mm (%8 x %9 points)
</source>
        <translation>Výšková mapa %1 použita: X %2 až %3, Y %4 až %5 mm, výšky %6 až %7 mm (%8 × %9 bodů)
</translation>
    </message>
</context>
<context>
    <name>QSerialPort</name>
    <message>
        <source>Permission error while locking the device</source>
        <translation>Chyba oprávnění při zamykání zařízení</translation>
    </message>
</context>
<context>
    <name>ReplayTransport</name>
    <message>
        <source>replay of the serial trace %1</source>
        <translation>přehrávání sériového záznamu %1</translation>
    </message>
</context>
<context>
    <name>RotaryLineCli</name>
    <message>
        <source>frezka-cli run-line: the rotary unit must be a GVE114 (only it shares its line with other units): give a GVE114 profile, --rotary-a %1:PROFILE
</source>
        <translation>frezka-cli run-line: otočný stůl musí mít jednotku GVE114 (jen ta sdílí linku s dalšími jednotkami): zadejte profil GVE114, --rotary-a %1:PROFIL
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: the rotary unit&apos;s address %1 is the machine&apos;s unit&apos;s (unit.address of --machine): each unit on the line has its own address
</source>
        <translation>frezka-cli run-line: adresa %1 jednotky otočného stolu je adresou jednotky stroje (unit.address v --machine): každá jednotka na lince má svou vlastní adresu
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: the rotary unit&apos;s profile has no A axis (axes.a.present is false): give a profile that sets the A axis&apos;s scale, speeds and limits, --rotary-a %1:PROFILE
</source>
        <translation>frezka-cli run-line: profil jednotky otočného stolu nemá osu A (axes.a.present je false): zadejte profil, který nastavuje měřítko, rychlosti a limity osy A, --rotary-a %1:PROFIL
</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>varování: </translation>
    </message>
    <message>
        <source>%1:%2: a probe move that turns A cannot run with A on its own unit (--rotary-a): probe without moving A
</source>
        <translation>%1:%2: pohyb sondy, který otáčí osou A, nelze spustit s osou A na vlastní jednotce (--rotary-a): sondujte bez pohybu osy A
</translation>
    </message>
    <message>
        <source>%1:%2: internal error: the program was planned without a rest around each move that turns A; please report it with the program
</source>
        <translation>%1:%2: vnitřní chyba: program byl naplánován bez zastavení kolem každého pohybu, který otáčí osou A; nahlaste ji prosím i s programem
</translation>
    </message>
</context>
<context>
    <name>RunCli</name>
    <message>
        <source><byte value="xd"/>[%1] %2% line %3 ETA %4 </source>
        <translation><byte value="xd"/>[%1] %2% řádek %3 zbývá %4 </translation>
    </message>
    <message>
        <source>could not connect to the emulator</source>
        <translation>nelze se připojit k emulátoru</translation>
    </message>
    <message>
        <source>%1: %2
</source>
        <translation>%1: %2
</translation>
    </message>
    <message>
        <source>the job did not finish</source>
        <translation>úloha nedoběhla</translation>
    </message>
    <message>
        <source>%1: the unit&apos;s counters differ from the planned end position
</source>
        <translation>%1: čítače jednotky se liší od plánované koncové polohy
</translation>
    </message>
    <message>
        <source>warning: %1
</source>
        <translation>varování: %1
</translation>
    </message>
    <message>
        <source>the scripted hold at line %1 failed %2: %3</source>
        <translation>naskriptované zastavení na řádku %1 selhalo (%2): %3</translation>
    </message>
    <message>
        <source>%1%2. Press Enter to continue.
</source>
        <translation>%1%2. Pokračujte klávesou Enter.
</translation>
    </message>
    <message>
        <source>No answer on standard input: the job ends at the stop (use --continue-at-stops for an unattended run).
</source>
        <translation>Na standardním vstupu žádná odpověď: úloha končí na zastavení (pro běh bez obsluhy použijte --continue-at-stops).
</translation>
    </message>
    <message>
        <source>Run from line %1. %2
</source>
        <translation>Spuštění od řádku %1. %2
</translation>
    </message>
    <message>
        <source>serial trace saved to %1
</source>
        <translation>sériový záznam uložen do %1
</translation>
    </message>
    <message>
        <source>usage: frezka-cli run FILE %1 [--port PATH|sim] [--baud N] [--latency-ms N] [--faults RATE --seed N] [--clock virtual|real] [--home] [--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]] [--continue-at-stops] [--from-line N] [--trace FILE] [--surface SPEC [--cut-depth]]
</source>
        <translation>použití: frezka-cli run SOUBOR %1 [--port CESTA|sim] [--baud N] [--latency-ms N] [--faults PODÍL --seed N] [--clock virtual|real] [--home] [--return-to-path] [--feed-override PROCENTA] [--hold-at-line N [--lift]] [--continue-at-stops] [--from-line N] [--trace SOUBOR] [--surface POPIS [--cut-depth]]
</translation>
    </message>
    <message>
        <source>frezka-cli run: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm), such as plane:-5,0.001,0
</source>
        <translation>frezka-cli run: --surface %1: očekáváno plane:Z0,DZDX,DZDY, sine:AMP,PERIODA[,Z0] nebo warp:Z0,DZDX,DZDY,AMP,PERIODA (mm stroje), např. plane:-5,0.001,0
</translation>
    </message>
    <message>
        <source>%1:%2: the path after this probe depends on where it stops: each part is planned when the probe before it has run
</source>
        <translation>%1:%2: dráha za touto sondou závisí na tom, kde se zastaví: každá část se naplánuje, až proběhne sonda před ní
</translation>
    </message>
    <message>
        <source>line %1: the probe has run; the rest of the program runs as interpreted with its result
</source>
        <translation>řádek %1: sonda proběhla; zbytek programu běží podle jejího výsledku
</translation>
    </message>
</context>
<context>
    <name>RunFromLine</name>
    <message>
        <source>line %1 is never reached: the program ends on line %2. Choose a line up to %2.</source>
        <translation>program na řádek %1 nikdy nedojde: končí na řádku %2. Zvolte řádek nejvýše %2.</translation>
    </message>
    <message>
        <source>line %1 is inside the subroutine o%2 (defined on line %3), which runs only when it is called. Choose the line that calls it, or a line outside the subroutine.</source>
        <translation>řádek %1 leží v podprogramu o%2 (definovaném na řádku %3), který se provede jen při volání. Zvolte řádek, který jej volá, nebo řádek mimo podprogram.</translation>
    </message>
    <message>
        <source>line %1 runs only inside the subroutine o%2, called on line %3. Choose line %3, or a line outside the subroutine.</source>
        <translation>řádek %1 se provede jen uvnitř podprogramu o%2 volaného na řádku %3. Zvolte řádek %3 nebo řádek mimo podprogram.</translation>
    </message>
    <message>
        <source>line %1 is inside the loop o%2 that opens on line %3, so the program runs it more than once. Choose line %3, or a line after the loop.</source>
        <translation>řádek %1 leží ve smyčce o%2, která začíná na řádku %3, takže jej program provede víckrát. Zvolte řádek %3 nebo řádek za smyčkou.</translation>
    </message>
    <message>
        <source>line %1 is never run: the program skips it at o%2 on line %3 (a branch or a loop it does not take). Choose a line the program runs.</source>
        <translation>řádek %1 se nikdy neprovede: program jej přeskočí u o%2 na řádku %3 (větev nebo smyčka, do které nevstoupí). Zvolte řádek, který program provádí.</translation>
    </message>
    <message>
        <source>%1:%2: cannot run from this line: %3</source>
        <translation>%1:%2: od tohoto řádku nelze spustit: %3</translation>
    </message>
    <message>
        <source>no feed is in force at line %1 (no F word yet, or G93 inverse time). Choose a line after an F word in G94.</source>
        <translation>na řádku %1 neplatí žádný posuv (ještě nebylo slovo F, nebo platí G93, inverzní čas). Zvolte řádek za slovem F v režimu G94.</translation>
    </message>
    <message>
        <source>tool %1 (length %2 mm)</source>
        <translation>nástroj %1 (délka %2 mm)</translation>
    </message>
    <message>
        <source>no tool loaded by the program</source>
        <translation>program nezaložil žádný nástroj</translation>
    </message>
    <message>
        <source>Line %1: %2; the approach crosses at Z %3 (machine) and comes down at the feed to X %4 Y %5 Z %6 (machine).</source>
        <translation>Řádek %1: %2; najetí přejíždí ve výšce Z %3 (strojně) a posuvem sjede na X %4 Y %5 Z %6 (strojně).</translation>
    </message>
    <message>
        <source>line %1 is in a path with cutter radius compensation, turned on on line %2: where the tool runs there depends on the moves before. Choose line %2 or a line before it, or a line after G40.</source>
        <translation>řádek %1 leží v dráze s korekcí poloměru nástroje zapnutou na řádku %2: kudy tam nástroj pojede, závisí na předchozích pohybech. Zvolte řádek %2 nebo řádek před ním, nebo řádek za G40.</translation>
    </message>
</context>
<context>
    <name>RunLineCli</name>
    <message>
        <source>frezka-cli run-line: cannot read --unit &apos;%1&apos;: write ADDRESS:FILE with an address 0..6, e.g. --unit 1:part.nc
</source>
        <translation>frezka-cli run-line: --unit &apos;%1&apos; nelze přečíst: napište ADRESA:SOUBOR s adresou 0..6, např. --unit 1:dil.nc
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: address %1 is given twice: each unit on the line has its own address
</source>
        <translation>frezka-cli run-line: adresa %1 je uvedena dvakrát: každá jednotka na lince má vlastní adresu
</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>varování: </translation>
    </message>
    <message>
        <source>unit %1: %2
</source>
        <translation>jednotka %1: %2
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: %1
</source>
        <translation>frezka-cli run-line: %1
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: unit %1: a %2 answers on address 0 only; give it address 0, or use a GVE114 profile (--machine gve114)
</source>
        <translation>frezka-cli run-line: jednotka %1: %2 odpovídá jen na adrese 0; dejte jí adresu 0, nebo použijte profil GVE114 (--machine gve114)
</translation>
    </message>
    <message>
        <source>usage: frezka-cli run-line --unit ADDRESS:FILE[:PROFILE] [--unit ...]... %1 [--port PATH|sim] [--baud N] [--latency-ms N] [--quiet-ms N] [--timeout S]
       frezka-cli run-line --machine PROFILE --rotary-a ADDRESS[:PROFILE] [options as above] FILE
</source>
        <translation>použití: frezka-cli run-line --unit ADRESA:SOUBOR[:PROFIL] [--unit ...]... %1 [--port CESTA|sim] [--baud N] [--latency-ms N] [--quiet-ms N] [--timeout S]
       frezka-cli run-line --machine PROFIL --rotary-a ADRESA[:PROFIL] [volby jako výše] SOUBOR
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: cannot read --rotary-a &apos;%1&apos;: write the rotary unit&apos;s address 1..6, once, and optionally its profile, e.g. --rotary-a 1:rotary.json
</source>
        <translation>frezka-cli run-line: nelze přečíst --rotary-a &apos;%1&apos;: napište jednou adresu jednotky otočného stolu 1..6 a případně její profil, např. --rotary-a 1:rotary.json
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: --rotary-a runs one program on the machine&apos;s unit and the rotary unit: give the program&apos;s FILE and no --unit
</source>
        <translation>frezka-cli run-line: --rotary-a spouští jeden program na jednotce stroje a jednotce otočného stolu: zadejte SOUBOR programu a žádné --unit
</translation>
    </message>
</context>
<context>
    <name>SerialTrace</name>
    <message>
        <source>line %1: not an entry (time in ms, then &gt;, &lt; or =, then the bytes): %2</source>
        <translation>řádek %1: není záznam (čas v ms, pak &gt;, &lt; nebo =, pak bajty): %2</translation>
    </message>
    <message>
        <source>line %1: the direction must be &gt; (to the unit), &lt; (from the unit) or = (an event), not &apos;%2&apos;</source>
        <translation>řádek %1: směr musí být &gt; (do jednotky), &lt; (z jednotky) nebo = (událost), ne &apos;%2&apos;</translation>
    </message>
    <message>
        <source>line %1: a bad escape in &apos;%2&apos; (use \r, \n, \\ or \xHH)</source>
        <translation>řádek %1: chybná úniková sekvence v &apos;%2&apos; (použijte \r, \n, \\ nebo \xHH)</translation>
    </message>
    <message>
        <source>line %1: the hex column does not match the text &apos;%2&apos;: correct it or delete it (from the &apos;|&apos; on)</source>
        <translation>řádek %1: šestnáctkový sloupec neodpovídá textu &apos;%2&apos;: opravte ho, nebo ho smažte (od &apos;|&apos; dál)</translation>
    </message>
    <message>
        <source>line 1: not a Frezka serial trace (it must start with &apos;%1&apos;)</source>
        <translation>řádek 1: není sériový záznam Frezky (musí začínat &apos;%1&apos;)</translation>
    </message>
    <message>
        <source>trace line %1: the driver sent &apos;%2&apos; before the unit&apos;s line &apos;%3&apos; that the trace has first</source>
        <translation>řádek záznamu %1: ovladač poslal &apos;%2&apos; dříve než řádek jednotky &apos;%3&apos;, který je v záznamu první</translation>
    </message>
    <message>
        <source>trace line %1: expected &apos;%2&apos;, got &apos;%3&apos; (the last unit line given was trace line %4)</source>
        <translation>řádek záznamu %1: očekáváno &apos;%2&apos;, přišlo &apos;%3&apos; (poslední předaný řádek jednotky byl řádek záznamu %4)</translation>
    </message>
</context>
<context>
    <name>SerialTransport</name>
    <message>
        <source>%1 at %2 Bd</source>
        <translation>%1 při %2 Bd</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>%1 nelze otevřít: %2</translation>
    </message>
    <message>
        <source>cannot configure %1: %2</source>
        <translation>%1 nelze nastavit: %2</translation>
    </message>
    <message>
        <source>write to %1: port not open</source>
        <translation>zápis do %1: port není otevřen</translation>
    </message>
    <message>
        <source>short write to %1: %2 of %3 bytes (%4)</source>
        <translation>neúplný zápis do %1: %2 z %3 bajtů (%4)</translation>
    </message>
    <message>
        <source>%1: %2 (ignored)</source>
        <translation>%1: %2 (přeskočeno)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>cannot open %1: permission denied. The port belongs to the group %2: join it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again.</source>
        <translation>%1 nelze otevřít: přístup odepřen. Port patří skupině %2: přidejte se do ní příkazem &quot;sudo usermod -aG %2 $USER&quot;, pak se odhlaste a znovu přihlaste.</translation>
    </message>
</context>
<context>
    <name>TraceRecorder</name>
    <message>
        <source>cannot write the serial trace to %1: %2. Choose a folder you may write to.</source>
        <translation>sériový záznam nelze zapsat do %1: %2. Zvolte složku, do které smíte zapisovat.</translation>
    </message>
</context>
<context>
    <name>TracingTransport</name>
    <message>
        <source>serial trace saved to %1 (%2)</source>
        <translation>sériový záznam uložen do %1 (%2)</translation>
    </message>
</context>
<context>
    <name>frezka::app</name>
    <message>
        <source>data: %1</source>
        <translation>data: %1</translation>
    </message>
    <message>
        <source>(not found)</source>
        <translation>(nenalezena)</translation>
    </message>
</context>
<context>
    <name>frezka::cli</name>
    <message>
        <source>note: </source>
        <translation>poznámka: </translation>
    </message>
    <message>
        <source>Check a G-code program against the machine&apos;s travel: every error, or a summary</source>
        <translation>Zkontroluje program v G-kódu vůči pojezdům stroje: všechny chyby, nebo souhrn</translation>
    </message>
    <message>
        <source>Transfer programs to/from ANC/K51 grinding controls; Z-position link</source>
        <translation>Přenos programů do/z řídicích systémů brusek ANC/K51; spojení polohy Z</translation>
    </message>
    <message>
        <source>Plan a G-code program for a machine and print the unit commands</source>
        <translation>Naplánuje program v G-kódu pro stroj a vypíše příkazy jednotky</translation>
    </message>
    <message>
        <source>Run a G-code job on a GVE unit or the emulator, with progress and a JSON report</source>
        <translation>Spustí úlohu v G-kódu na jednotce GVE nebo v emulátoru, s průběhem a zprávou v JSON</translation>
    </message>
    <message>
        <source>Interpret a G-code program and print its moves as JSON Lines</source>
        <translation>Interpretuje program v G-kódu a vypíše jeho pohyby jako JSON Lines</translation>
    </message>
    <message>
        <source>%1:%2: %3%4 %5 is %6 mm above the machine&apos;s travel (%4 %7 .. %8 mm)</source>
        <translation>%1:%2: %3%4 %5 je %6 mm nad pojezdem stroje (%4 %7 .. %8 mm)</translation>
    </message>
    <message>
        <source>%1:%2: %3%4 %5 is %6 mm below the machine&apos;s travel (%4 %7 .. %8 mm)</source>
        <translation>%1:%2: %3%4 %5 je %6 mm pod pojezdem stroje (%4 %7 .. %8 mm)</translation>
    </message>
    <message>
        <source>; the program goes %1 mm beyond it at line %2</source>
        <translation>; program jej přesahuje nejvíce o %1 mm na řádku %2</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>varování: </translation>
    </message>
    <message>
        <source>%1: the program fits the machine&apos;s travel once its work zero is set: give it with --offset G54:X,Y,Z (--offset G54:%2,%3,%4 puts it inside)
</source>
        <translation>%1: program se do pojezdů stroje vejde, jakmile bude nastavena jeho pracovní nula: zadejte ji volbou --offset G54:X,Y,Z (--offset G54:%2,%3,%4 jej umístí dovnitř)
</translation>
    </message>
    <message>
        <source>%1: the program is larger than the machine&apos;s travel
</source>
        <translation>%1: program je větší než pojezdy stroje
</translation>
    </message>
    <message>
        <source>exit codes:
  0  done: the program is good (check), planned (plan), ran to its end (run)
  1  an error in the input or on the machine: a G-code error, a line beyond the machine&apos;s travel, a bad profile, a job that did not finish (on stderr, with the line)
  2  bad usage: an unknown command or option, a malformed value
</source>
        <translation>návratové kódy:
  0  hotovo: program je v pořádku (check), naplánován (plan), doběhl do konce (run)
  1  chyba ve vstupu nebo na stroji: chyba G-kódu, řádek mimo pojezdy stroje, chybný profil, nedokončená úloha (na standardní chybový výstup, s řádkem)
  2  chybné použití: neznámý příkaz nebo volba, chybně zapsaná hodnota
</translation>
    </message>
    <message>
        <source>usage: frezka-cli COMMAND [ARGS...]

commands:
</source>
        <translation>použití: frezka-cli PŘÍKAZ [ARGUMENTY...]

příkazy:
</translation>
    </message>
    <message>
        <source>frezka-cli: unknown command &apos;%1&apos;
</source>
        <translation>frezka-cli: neznámý příkaz „%1“
</translation>
    </message>
    <message>
        <source>
work offsets: --offset G54:X,Y,Z sets where the program&apos;s zero is on the machine (machine mm; G54 .. G59.3, repeatable); --work-zero X,Y,Z is --offset G54:X,Y,Z.
operator stops: at M0, M1 and M6 frezka-cli run waits for Enter; --continue-at-stops runs on without an operator.
run from a line: frezka-cli run --from-line N starts the job at line N with the program&apos;s state there (tool, spindle, coolant, feed, modes, offsets), after a safe approach (spindle on, Z up to the safe height, X/Y across, Z down at the feed).

</source>
        <translation>
pracovní posunutí: --offset G54:X,Y,Z určí, kde na stroji leží nula programu (strojní mm; G54 .. G59.3, lze opakovat); --work-zero X,Y,Z je totéž co --offset G54:X,Y,Z.
zastavení pro obsluhu: na M0, M1 a M6 čeká frezka-cli run na Enter; --continue-at-stops pokračuje bez obsluhy.
spuštění od řádku: frezka-cli run --from-line N spustí úlohu na řádku N se stavem programu na tomto řádku (nástroj, vřeteno, chlazení, posuv, režimy, posunutí) po bezpečném najetí (vřeteno zapnuto, Z nahoru do bezpečné výšky, X/Y na místo, Z dolů posuvem).

</translation>
    </message>
    <message>
        <source>--version prints the version and the data folder (shipped machine profiles and sample programs).

</source>
        <translation>--version vypíše verzi a složku dat (dodávané profily strojů a ukázkové programy).

</translation>
    </message>
    <message>
        <source>Commission a unit: identify it, check the protocol&apos;s readings, measure the link, read the EEPROM, then (in a terminal) test each axis, switch, the spindle, the outputs and homing after asking; write a report and an updated profile</source>
        <translation>Uvedení jednotky do provozu: identifikuje ji, ověří výklady protokolu, změří linku, přečte EEPROM, pak (v terminálu) po dotazu vyzkouší každou osu, spínače, vřeteno, výstupy a referování; zapíše protokol a upravený profil</translation>
    </message>
    <message>
        <source>Probe a height map on the unit (G38.2 on a grid) and write its file</source>
        <translation>Nasondovat výškovou mapu na jednotce (G38.2 v mřížce) a zapsat ji do souboru</translation>
    </message>
    <message>
        <source>Run a program on each of several units sharing one serial line</source>
        <translation>Spustit program na každé z několika jednotek na jedné sériové lince</translation>
    </message>
    <message>
        <source>Probe the work&apos;s zero (Z from a touch plate, X/Y from an edge or a corner) or a tool&apos;s length on the tool sensor (fast then slow G38.2)</source>
        <translation>Sondovat nulu obrobku (Z dotykovou destičkou, X/Y z hrany nebo rohu) nebo délku nástroje na snímači nástrojů (G38.2 rychle, pak pomalu)</translation>
    </message>
    <message>
        <source>%1:%2: note: after this line the path depends on the probe&apos;s result; it is checked here as if the probe ended at its programmed end (run plans it once the probe has run)
</source>
        <translation>%1:%2: poznámka: za tímto řádkem závisí dráha na výsledku sondy; zde se kontroluje, jako by sonda skončila v naprogramovaném koncovém bodě (run ji naplánuje, až sonda proběhne)
</translation>
    </message>
</context>
<context>
    <name>frezka::driver</name>
    <message>
        <source>%1 is not possible now (the machine is %2)</source>
        <translation>%1 nyní není možné (stav stroje: %2)</translation>
    </message>
    <message>
        <source>Wait until the machine is in a state that allows it, or stop what it is doing.</source>
        <translation>Počkejte, až to stav stroje dovolí, nebo zastavte, co právě dělá.</translation>
    </message>
    <message>
        <source>A job can start only when the machine is ready (it is %1)</source>
        <translation>Úlohu lze spustit jen tehdy, když je stroj připraven (stav: %1)</translation>
    </message>
    <message>
        <source>Wait until the machine is ready, then start the job again.</source>
        <translation>Počkejte, až bude stroj připraven, a spusťte úlohu znovu.</translation>
    </message>
    <message>
        <source>The job&apos;s progress is still being checked against the unit&apos;s counters</source>
        <translation>Postup úlohy se ještě ověřuje podle čítačů jednotky</translation>
    </message>
    <message>
        <source>Wait a moment, then continue.</source>
        <translation>Chvíli počkejte a pak pokračujte.</translation>
    </message>
    <message>
        <source>The tool is lifted and the job&apos;s queue is kept in the unit (K)</source>
        <translation>Nástroj je zvednutý a fronta úlohy je uchována v jednotce (K)</translation>
    </message>
    <message>
        <source>Lower the tool first, then abort.</source>
        <translation>Nejprve spusťte nástroj dolů, pak úlohu přerušte.</translation>
    </message>
    <message>
        <source>The machine profile homes no axis</source>
        <translation>Profil stroje nenajíždí do reference žádnou osu</translation>
    </message>
    <message>
        <source>Set a homing order for the axes (axes.*.homing.order) in the machine profile.</source>
        <translation>Nastavte v profilu stroje pořadí najíždění os do reference (axes.*.homing.order).</translation>
    </message>
    <message>
        <source>The machine profile does not home that axis</source>
        <translation>Profil stroje tuto osu do reference nenajíždí</translation>
    </message>
    <message>
        <source>Give the axis a homing order (axes.*.homing.order) in the machine profile.</source>
        <translation>Dejte ose v profilu stroje pořadí najíždění do reference (axes.*.homing.order).</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) cannot set one axis&apos;s counter (N&lt;axis&gt; needs v19), and N zeroes every counter</source>
        <translation>Firmware této jednotky (v%1) neumí nastavit čítač jedné osy (N&lt;osa&gt; vyžaduje v19) a N nuluje všechny čítače</translation>
    </message>
    <message>
        <source>Home all the machine&apos;s axes together, each with home position 0.</source>
        <translation>Najeďte do reference všechny osy stroje najednou, každou s referenční polohou 0.</translation>
    </message>
    <message>
        <source>The axis is outside its soft limits</source>
        <translation>Osa je mimo své softwarové limity</translation>
    </message>
    <message>
        <source>Home the machine first.</source>
        <translation>Nejprve najeďte strojem do reference.</translation>
    </message>
    <message>
        <source>The axis is at its soft limit</source>
        <translation>Osa je na svém softwarovém limitu</translation>
    </message>
    <message>
        <source>Jog in the other direction.</source>
        <translation>Pohybujte opačným směrem.</translation>
    </message>
    <message>
        <source>This machine has no such axis</source>
        <translation>Tento stroj takovou osu nemá</translation>
    </message>
    <message>
        <source>Use one of the axes the machine profile has.</source>
        <translation>Použijte některou z os, které profil stroje má.</translation>
    </message>
    <message>
        <source>This machine has no such axis or direction</source>
        <translation>Tento stroj takovou osu nebo směr nemá</translation>
    </message>
    <message>
        <source>The unit program has %1 axes</source>
        <translation>Program pro jednotku má %1 os</translation>
    </message>
    <message>
        <source>Plan the program again for this machine.</source>
        <translation>Naplánujte program znovu pro tento stroj.</translation>
    </message>
    <message>
        <source>The unit program has 4 axes but the %1 has 3</source>
        <translation>Program pro jednotku má 4 osy, ale %1 má 3</translation>
    </message>
    <message>
        <source>The program was planned from %1 steps on axis %2 but the machine is at %3</source>
        <translation>Program byl naplánován od %1 kroků v ose %2, ale stroj je na %3</translation>
    </message>
    <message>
        <source>Line %1: the plan uses VK, which this unit&apos;s firmware (v%2) lacks (it needs v19)</source>
        <translation>Řádek %1: plán používá VK, které firmware této jednotky (v%2) nemá (vyžaduje v19)</translation>
    </message>
    <message>
        <source>Plan in VN (motion.speedMode &quot;vn&quot;), or set unit.firmwareVersion in the profile.</source>
        <translation>Plánujte ve VN (motion.speedMode &quot;vn&quot;) nebo nastavte v profilu unit.firmwareVersion.</translation>
    </message>
    <message>
        <source>Line %1: the command cannot be sent: %2</source>
        <translation>Řádek %1: příkaz nelze odeslat: %2</translation>
    </message>
    <message>
        <source>Check the machine profile&apos;s limits and plan the program again.</source>
        <translation>Zkontrolujte limity v profilu stroje a naplánujte program znovu.</translation>
    </message>
    <message>
        <source>Off the planned path the unit holds no queue to keep</source>
        <translation>Mimo plánovanou dráhu jednotka nemá žádnou frontu k uchování</translation>
    </message>
    <message>
        <source>Continue (it lifts the tool and returns to the path) or abort.</source>
        <translation>Pokračujte (nástroj se zvedne a vrátí na dráhu), nebo přerušte.</translation>
    </message>
    <message>
        <source>The machine profile sets no tool lift height</source>
        <translation>Profil stroje nenastavuje výšku zvednutí nástroje</translation>
    </message>
    <message>
        <source>Set motion.toolLiftMm in the machine profile.</source>
        <translation>Nastavte v profilu stroje motion.toolLiftMm.</translation>
    </message>
    <message>
        <source>Z is at its upper soft limit: no room to lift the tool</source>
        <translation>Z je na horním softwarovém limitu: nástroj není kam zvednout</translation>
    </message>
    <message>
        <source>Continue without lifting, or abort the job.</source>
        <translation>Pokračujte bez zvednutí, nebo úlohu přerušte.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) has no MPG handwheel; it needs v10</source>
        <translation>Firmware této jednotky (v%1) nemá ruční kolečko MPG; vyžaduje v10</translation>
    </message>
    <message>
        <source>Jog with the buttons or the keyboard instead.</source>
        <translation>Pohybujte raději tlačítky nebo klávesnicí.</translation>
    </message>
    <message>
        <source>This unit has no MPG handwheel</source>
        <translation>Tato jednotka nemá ruční kolečko MPG</translation>
    </message>
    <message>
        <source>Spindle speed %1 rpm is outside 0 … %2 rpm</source>
        <translation>Otáčky vřetena %1 ot/min jsou mimo 0 … %2 ot/min</translation>
    </message>
    <message>
        <source>Enter a speed within the machine profile&apos;s range (spindle.maxRpm).</source>
        <translation>Zadejte otáčky v rozsahu profilu stroje (spindle.maxRpm).</translation>
    </message>
    <message>
        <source>This unit has no feed override (XM)</source>
        <translation>Tato jednotka nemá korekci posuvu (XM)</translation>
    </message>
    <message>
        <source>Change the feed in the program instead.</source>
        <translation>Změňte raději posuv v programu.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) has no XM feed override; it needs v19</source>
        <translation>Firmware této jednotky (v%1) nemá korekci posuvu XM; vyžaduje v19</translation>
    </message>
    <message>
        <source>The feed override cannot be set: %1</source>
        <translation>Korekci posuvu nelze nastavit: %1</translation>
    </message>
    <message>
        <source>Choose a value within the unit&apos;s range.</source>
        <translation>Zvolte hodnotu v rozsahu jednotky.</translation>
    </message>
    <message>
        <source>Empty command</source>
        <translation>Prázdný příkaz</translation>
    </message>
    <message>
        <source>Type a unit command after &apos;!&apos;.</source>
        <translation>Napište za &apos;!&apos; příkaz pro jednotku.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be sent to the unit: %2</source>
        <translation>&apos;%1&apos; nelze poslat jednotce: %2</translation>
    </message>
    <message>
        <source>See the unit&apos;s command list (docs/gve-protocol.md).</source>
        <translation>Viz seznam příkazů jednotky (docs/gve-protocol.md).</translation>
    </message>
    <message>
        <source>&apos;%1&apos; would disturb the running job</source>
        <translation>&apos;%1&apos; by narušil běžící úlohu</translation>
    </message>
    <message>
        <source>Send it when the job has ended.</source>
        <translation>Pošlete ho, až úloha skončí.</translation>
    </message>
    <message>
        <source>The new speed cannot be set: %1</source>
        <translation>Novou rychlost nelze nastavit: %1</translation>
    </message>
    <message>
        <source>Enter a lower feed, or leave it unchanged.</source>
        <translation>Zadejte nižší posuv, nebo ho ponechte beze změny.</translation>
    </message>
    <message>
        <source>%1: the unit answered: %2</source>
        <translation>%1: jednotka odpověděla: %2</translation>
    </message>
    <message>
        <source>Check the machine and the connection, then try again.</source>
        <translation>Zkontrolujte stroj a spojení a zkuste to znovu.</translation>
    </message>
    <message>
        <source>%1: the link failed: %2</source>
        <translation>%1: spojení selhalo: %2</translation>
    </message>
    <message>
        <source>Check the cable and that the unit is on, then connect again.</source>
        <translation>Zkontrolujte kabel a zda je jednotka zapnutá, pak se znovu připojte.</translation>
    </message>
    <message>
        <source>Line %1: the unit refused &apos;%2&apos; (%3)</source>
        <translation>Řádek %1: jednotka odmítla &apos;%2&apos; (%3)</translation>
    </message>
    <message>
        <source>Check the machine profile against the unit (variant, firmware, limits).</source>
        <translation>Porovnejte profil stroje s jednotkou (varianta, firmware, limity).</translation>
    </message>
    <message>
        <source>The link was lost: %1</source>
        <translation>Spojení bylo ztraceno: %1</translation>
    </message>
    <message>
        <source>The job is kept: reconnect, then continue.</source>
        <translation>Úloha je uchována: znovu se připojte a pokračujte.</translation>
    </message>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Nelze se připojit: %1</translation>
    </message>
    <message>
        <source>Check the port in the settings, the cable, and that the unit is on.</source>
        <translation>Zkontrolujte port v nastavení, kabel a zda je jednotka zapnutá.</translation>
    </message>
    <message>
        <source>The unit reports firmware &apos;%1&apos; but the machine profile is for a %2</source>
        <translation>Jednotka hlásí firmware &apos;%1&apos;, ale profil stroje je pro %2</translation>
    </message>
    <message>
        <source>Choose the matching machine profile.</source>
        <translation>Zvolte odpovídající profil stroje.</translation>
    </message>
    <message>
        <source>The unit reports firmware v%1 but the machine profile says v%2; plans for the profile&apos;s firmware may use what this one lacks (MPG and EEPROM floats need v10; VK, VL, XM and setting one axis&apos;s counter v19)</source>
        <translation>Jednotka hlásí firmware v%1, ale profil stroje uvádí v%2; plány pro firmware z profilu mohou použít, co tento nemá (MPG a reálná čísla v EEPROM vyžadují v10; VK, VL, XM a nastavení čítače jedné osy v19)</translation>
    </message>
    <message>
        <source>Set unit.firmwareVersion to %1 in the machine profile.</source>
        <translation>Nastavte v profilu stroje unit.firmwareVersion na %1.</translation>
    </message>
    <message>
        <source>Line %1: unknown unit program operation</source>
        <translation>Řádek %1: neznámá operace programu jednotky</translation>
    </message>
    <message>
        <source>Plan the program again.</source>
        <translation>Naplánujte program znovu.</translation>
    </message>
    <message>
        <source>Homing axis %1: the home switch was not found within the configured travel</source>
        <translation>Reference osy %1: referenční spínač nebyl v nastavené dráze nalezen</translation>
    </message>
    <message>
        <source>Check the switch and its wiring, and the axis&apos;s homing travel in the profile.</source>
        <translation>Zkontrolujte spínač a jeho zapojení a dráhu najíždění osy v profilu.</translation>
    </message>
    <message>
        <source>Homing axis %1: %2</source>
        <translation>Reference osy %1: %2</translation>
    </message>
    <message>
        <source>Check the axis&apos;s homing settings in the machine profile.</source>
        <translation>Zkontrolujte nastavení reference osy v profilu stroje.</translation>
    </message>
    <message>
        <source>Line %1: the probe input is already in the state the probe move waits for</source>
        <translation>Řádek %1: vstup sondy už je ve stavu, na který pohyb sondy čeká</translation>
    </message>
    <message>
        <source>Check the probe and its wiring.</source>
        <translation>Zkontrolujte sondu a její zapojení.</translation>
    </message>
    <message>
        <source>Line %1: the probe move ended without the probe tripping</source>
        <translation>Řádek %1: pohyb sondy skončil, aniž sonda sepnula</translation>
    </message>
    <message>
        <source>Check the probe and the workpiece, then run the job again.</source>
        <translation>Zkontrolujte sondu a obrobek a spusťte úlohu znovu.</translation>
    </message>
    <message>
        <source>Line %1: the probe tripped at %2 steps; the rest of the program was planned from the probe&apos;s end point</source>
        <translation>Řádek %1: sonda sepnula na %2 krocích; zbytek programu byl naplánován od koncového bodu sondy</translation>
    </message>
    <message>
        <source>The unit&apos;s counters match no point the job has reached; the job cannot resume exactly</source>
        <translation>Čítače jednotky neodpovídají žádnému bodu, kterého úloha dosáhla; úlohu nelze přesně obnovit</translation>
    </message>
    <message>
        <source>Home the machine and start the job again.</source>
        <translation>Najeďte strojem do reference a spusťte úlohu znovu.</translation>
    </message>
    <message>
        <source>The unit&apos;s counters match several points of the job; cannot tell how far it got</source>
        <translation>Čítače jednotky odpovídají několika bodům úlohy; nelze určit, kam až došla</translation>
    </message>
    <message>
        <source>Abort the job.</source>
        <translation>Přerušte úlohu.</translation>
    </message>
    <message>
        <source>The machine did not arrive back on the planned path after %1 attempts</source>
        <translation>Stroj se ani po %1 pokusech nevrátil na plánovanou dráhu</translation>
    </message>
    <message>
        <source>Abort the job and check the machine.</source>
        <translation>Přerušte úlohu a zkontrolujte stroj.</translation>
    </message>
    <message>
        <source>The machine left the planned path: %1. A command was damaged on the serial line in a way its checksum cannot show</source>
        <translation>Stroj opustil plánovanou dráhu: %1. Příkaz byl na sériové lince poškozen tak, že to kontrolní součet nepozná</translation>
    </message>
    <message>
        <source>Check the workpiece. Continue lifts the tool, returns to line %2 and runs the job on from there; or abort the job.</source>
        <translation>Zkontrolujte obrobek. Pokračovat zvedne nástroj, vrátí se na řádek %2 a odtud úlohu dokončí; nebo úlohu přerušte.</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pozastaveno</translation>
    </message>
    <message>
        <source>Continue, or lift the tool to change or clean it.</source>
        <translation>Pokračujte, nebo zvedněte nástroj, abyste ho vyměnili či očistili.</translation>
    </message>
    <message>
        <source>Program stop (M0) at line %1</source>
        <translation>Programový stop (M0) na řádku %1</translation>
    </message>
    <message>
        <source>Do what the program asks, then continue.</source>
        <translation>Udělejte, co program žádá, a pak pokračujte.</translation>
    </message>
    <message>
        <source>Optional stop (M1) at line %1</source>
        <translation>Volitelný stop (M1) na řádku %1</translation>
    </message>
    <message>
        <source>Tool change (M6) at line %1: change to tool %2</source>
        <translation>Výměna nástroje (M6) na řádku %1: vyměňte za nástroj %2</translation>
    </message>
    <message>
        <source>Lift the tool, change it to tool %2, lower it and continue.</source>
        <translation>Zvedněte nástroj, vyměňte ho za nástroj %2, spusťte ho dolů a pokračujte.</translation>
    </message>
    <message>
        <source>An input interrupt stopped the machine</source>
        <translation>Přerušení ze vstupu zastavilo stroj</translation>
    </message>
    <message>
        <source>Check the machine; when it is safe, continue or abort.</source>
        <translation>Zkontrolujte stroj; až to bude bezpečné, pokračujte nebo přerušte.</translation>
    </message>
    <message>
        <source>Stopped by input %1</source>
        <translation>Zastaveno vstupem %1</translation>
    </message>
    <message>
        <source>Stopped by input %1 (STOP button)</source>
        <translation>Zastaveno vstupem %1 (tlačítko STOP)</translation>
    </message>
    <message>
        <source>Tool lifted</source>
        <translation>Nástroj zvednut</translation>
    </message>
    <message>
        <source>Change or clean the tool, then lower it.</source>
        <translation>Vyměňte nebo očistěte nástroj a pak ho spusťte dolů.</translation>
    </message>
    <message>
        <source>Tool lowered</source>
        <translation>Nástroj spuštěn</translation>
    </message>
    <message>
        <source>Continue or abort.</source>
        <translation>Pokračujte, nebo přerušte.</translation>
    </message>
    <message>
        <source>Returning to the planned path</source>
        <translation>Návrat na plánovanou dráhu</translation>
    </message>
    <message>
        <source>Wait until the machine is back on the path.</source>
        <translation>Počkejte, až bude stroj zpět na dráze.</translation>
    </message>
    <message>
        <source>Link restored: checking the job&apos;s progress against the counters</source>
        <translation>Spojení obnoveno: ověřuje se postup úlohy podle čítačů</translation>
    </message>
    <message>
        <source>Wait until the check has finished, then continue.</source>
        <translation>Počkejte na konec ověření a pak pokračujte.</translation>
    </message>
    <message>
        <source>applying the new speed (XA)</source>
        <translation>použití nové rychlosti (XA)</translation>
    </message>
    <message>
        <source>arming the probe input</source>
        <translation>aktivace vstupu sondy</translation>
    </message>
    <message>
        <source>continuing (G)</source>
        <translation>pokračování (G)</translation>
    </message>
    <message>
        <source>disarming the probe input</source>
        <translation>deaktivace vstupu sondy</translation>
    </message>
    <message>
        <source>dropping the queue (D)</source>
        <translation>zrušení fronty (D)</translation>
    </message>
    <message>
        <source>dropping the queue (D) off the planned path</source>
        <translation>zrušení fronty (D) mimo plánovanou dráhu</translation>
    </message>
    <message>
        <source>ending the jog (D)</source>
        <translation>ukončení ručního pohybu (D)</translation>
    </message>
    <message>
        <source>identifying the unit (&apos;?&apos;)</source>
        <translation>identifikace jednotky (&apos;?&apos;)</translation>
    </message>
    <message>
        <source>identifying the unit (&apos;Q&apos;)</source>
        <translation>identifikace jednotky (&apos;Q&apos;)</translation>
    </message>
    <message>
        <source>jogging</source>
        <translation>ruční pohyb</translation>
    </message>
    <message>
        <source>keeping the queue (K)</source>
        <translation>uchování fronty (K)</translation>
    </message>
    <message>
        <source>lifting the tool</source>
        <translation>zvednutí nástroje</translation>
    </message>
    <message>
        <source>lowering the tool</source>
        <translation>spuštění nástroje</translation>
    </message>
    <message>
        <source>pausing (H)</source>
        <translation>pozastavení (H)</translation>
    </message>
    <message>
        <source>position poll</source>
        <translation>čtení polohy</translation>
    </message>
    <message>
        <source>probe move</source>
        <translation>pohyb sondy</translation>
    </message>
    <message>
        <source>raw command</source>
        <translation>přímý příkaz</translation>
    </message>
    <message>
        <source>re-sending the job&apos;s speed settings</source>
        <translation>opětovné odeslání rychlostí úlohy</translation>
    </message>
    <message>
        <source>reading the EEPROM</source>
        <translation>čtení EEPROM</translation>
    </message>
    <message>
        <source>reading the final position</source>
        <translation>čtení koncové polohy</translation>
    </message>
    <message>
        <source>reading the position</source>
        <translation>čtení polohy</translation>
    </message>
    <message>
        <source>reading the probe input</source>
        <translation>čtení vstupu sondy</translation>
    </message>
    <message>
        <source>reading the probe position</source>
        <translation>čtení polohy sondy</translation>
    </message>
    <message>
        <source>reading the probe result</source>
        <translation>čtení výsledku sondy</translation>
    </message>
    <message>
        <source>reading the status</source>
        <translation>čtení stavu</translation>
    </message>
    <message>
        <source>restoring the queue (R)</source>
        <translation>obnovení fronty (R)</translation>
    </message>
    <message>
        <source>returning to the planned path</source>
        <translation>návrat na plánovanou dráhu</translation>
    </message>
    <message>
        <source>setting the feed override (XM)</source>
        <translation>nastavení korekce posuvu (XM)</translation>
    </message>
    <message>
        <source>setting the jog speed</source>
        <translation>nastavení rychlosti ručního pohybu</translation>
    </message>
    <message>
        <source>setting the new speed</source>
        <translation>nastavení nové rychlosti</translation>
    </message>
    <message>
        <source>setting the speed to return to the path</source>
        <translation>nastavení rychlosti návratu na dráhu</translation>
    </message>
    <message>
        <source>setting the spindle</source>
        <translation>nastavení vřetena</translation>
    </message>
    <message>
        <source>starting the spindle</source>
        <translation>spuštění vřetena</translation>
    </message>
    <message>
        <source>status</source>
        <translation>stav</translation>
    </message>
    <message>
        <source>status poll</source>
        <translation>čtení stavu</translation>
    </message>
    <message>
        <source>stopping (H)</source>
        <translation>zastavení (H)</translation>
    </message>
    <message>
        <source>stopping (H) off the planned path</source>
        <translation>zastavení (H) mimo plánovanou dráhu</translation>
    </message>
    <message>
        <source>stopping the jog (H)</source>
        <translation>zastavení ručního pohybu (H)</translation>
    </message>
    <message>
        <source>stopping the probe move (H)</source>
        <translation>zastavení pohybu sondy (H)</translation>
    </message>
    <message>
        <source>stopping the spindle</source>
        <translation>zastavení vřetena</translation>
    </message>
    <message>
        <source>switching checksums</source>
        <translation>zapnutí kontrolních součtů</translation>
    </message>
    <message>
        <source>switching outputs</source>
        <translation>přepnutí výstupů</translation>
    </message>
    <message>
        <source>switching the MPG</source>
        <translation>přepnutí MPG</translation>
    </message>
    <message>
        <source>switching the MPG off</source>
        <translation>vypnutí MPG</translation>
    </message>
    <message>
        <source>testing packets</source>
        <translation>test paketů</translation>
    </message>
    <message>
        <source>raising queued speeds (XU)</source>
        <translation>zvýšení rychlostí ve frontě (XU)</translation>
    </message>
    <message>
        <source>lowering queued speeds (XD)</source>
        <translation>snížení rychlostí ve frontě (XD)</translation>
    </message>
    <message>
        <source>zeroing the counters (N)</source>
        <translation>vynulování čítačů (N)</translation>
    </message>
    <message>
        <source>setting T</source>
        <translation>nastavení T</translation>
    </message>
    <message>
        <source>setting VN</source>
        <translation>nastavení VN</translation>
    </message>
    <message>
        <source>setting the interrupt mask</source>
        <translation>nastavení masky přerušení</translation>
    </message>
    <message>
        <source>setting the input polarity</source>
        <translation>nastavení polarity vstupů</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavení</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračování</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Přerušení</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Najíždění do reference</translation>
    </message>
    <message>
        <source>Jogging</source>
        <translation>Ruční pohyb</translation>
    </message>
    <message>
        <source>Stopping the jog</source>
        <translation>Zastavení ručního pohybu</translation>
    </message>
    <message>
        <source>Writing the EEPROM</source>
        <translation>Zápis do EEPROM</translation>
    </message>
    <message>
        <source>Lifting the tool</source>
        <translation>Zvednutí nástroje</translation>
    </message>
    <message>
        <source>Lowering the tool</source>
        <translation>Spouštění nástroje</translation>
    </message>
    <message>
        <source>Switching the MPG</source>
        <translation>Přepnutí MPG</translation>
    </message>
    <message>
        <source>Setting the spindle</source>
        <translation>Nastavení vřetena</translation>
    </message>
    <message>
        <source>Switching outputs</source>
        <translation>Přepnutí výstupů</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>queue full</source>
        <translation>fronta plná</translation>
    </message>
    <message>
        <source>command not received completely in time</source>
        <translation>příkaz nebyl včas přijat celý</translation>
    </message>
    <message>
        <source>unknown command</source>
        <translation>neznámý příkaz</translation>
    </message>
    <message>
        <source>syntax error</source>
        <translation>chyba syntaxe</translation>
    </message>
    <message>
        <source>parameter out of range</source>
        <translation>parametr mimo rozsah</translation>
    </message>
    <message>
        <source>nothing to continue</source>
        <translation>není v čem pokračovat</translation>
    </message>
    <message>
        <source>not allowed while a vector runs</source>
        <translation>není dovoleno během vektoru</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Nepřipojeno</translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation>Připojování</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>Připraven</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Obrábění</translation>
    </message>
    <message>
        <source>Stopping</source>
        <translation>Zastavuji</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Spojení ztraceno</translation>
    </message>
    <message>
        <source>the link was closed</source>
        <translation>spojení bylo uzavřeno</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>bez odpovědi</translation>
    </message>
    <message>
        <source>setup</source>
        <translation>nastavení</translation>
    </message>
    <message>
        <source>Jog back to where it starts, or plan it again from here.</source>
        <translation>Najeďte zpět tam, kde začíná, nebo ho naplánujte znovu odsud.</translation>
    </message>
    <message>
        <source>Check the probe and the workpiece, then plan it again from here.</source>
        <translation>Zkontrolujte sondu a obrobek a pak program naplánujte znovu odsud.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) has no W: homing to a switch comes with IP64MPG v10</source>
        <translation>Firmware této jednotky (v%1) nemá W: najíždění na spínač přináší až IP64MPG v10</translation>
    </message>
    <message>
        <source>Set the position by hand (G92) or update the unit.</source>
        <translation>Nastavte polohu ručně (G92), nebo aktualizujte jednotku.</translation>
    </message>
    <message>
        <source>The spindle is starting: the job continues after its spin-up</source>
        <translation>Vřeteno se rozbíhá: program pokračuje po jeho rozběhu</translation>
    </message>
    <message>
        <source>Wait for the spin-up; the job then goes on by itself.</source>
        <translation>Počkejte na rozběh; program pak pokračuje sám.</translation>
    </message>
    <message>
        <source>The jog would end at %1 mm, outside the soft limits %2 .. %3 mm</source>
        <translation>Posuv by skončil na %1 mm, mimo softwarové limity %2 .. %3 mm</translation>
    </message>
    <message>
        <source>Jog a shorter distance.</source>
        <translation>Posuňte o kratší vzdálenost.</translation>
    </message>
    <message>
        <source>The jog is shorter than one step</source>
        <translation>Posuv je kratší než jeden krok</translation>
    </message>
    <message>
        <source>Choose a larger jog step.</source>
        <translation>Zvolte větší krok posuvu.</translation>
    </message>
    <message>
        <source>The lifted tool is still moving</source>
        <translation>Zvednutý nástroj se ještě pohybuje</translation>
    </message>
    <message>
        <source>Wait until it stands, then try again.</source>
        <translation>Počkejte, až se zastaví, a zkuste to znovu.</translation>
    </message>
    <message>
        <source>Homing axis %1: stopped before the end of its search leg (an input interrupt, or the home switch did not release within homing.backOffMm)</source>
        <translation>Reference osy %1: zastavena před koncem úseku hledání (přerušení ze vstupu, nebo se referenční spínač neuvolnil v rámci homing.backOffMm)</translation>
    </message>
    <message>
        <source>Check the inputs and the switch, then home again; the axis is not homed.</source>
        <translation>Zkontrolujte vstupy a spínač a najeďte referenci znovu; osa nemá referenci.</translation>
    </message>
    <message>
        <source>The tool did not arrive back at the lift point (%1 instead of %2)</source>
        <translation>Nástroj se nevrátil do bodu zvednutí (%1 místo %2)</translation>
    </message>
    <message>
        <source>The spindle starts; the job continues after its spin-up</source>
        <translation>Vřeteno se rozbíhá; program pokračuje po jeho rozběhu</translation>
    </message>
    <message>
        <source>Keep clear of the tool.</source>
        <translation>Nesahejte k nástroji.</translation>
    </message>
    <message>
        <source>This unit has no axis speed limits (VL): above 100 % an axis could run over its maximum</source>
        <translation>Tato jednotka nemá omezení rychlosti os (VL): nad 100 % by osa mohla překročit svou maximální rychlost</translation>
    </message>
    <message>
        <source>Raise the feed in the program instead.</source>
        <translation>Zvyšte raději posuv v programu.</translation>
    </message>
    <message>
        <source>This unit has no XM: a new feed would change only the queued vectors</source>
        <translation>Tato jednotka nemá XM: nový posuv by změnil jen vektory ve frontě</translation>
    </message>
    <message>
        <source>Lower the tool with the feed unchanged, then use the feed buttons (XD), which change the rest of the job.</source>
        <translation>Spusťte nástroj bez změny posuvu a pak použijte tlačítka posuvu (XD), která změní celý zbytek úlohy.</translation>
    </message>
    <message>
        <source>Y+ is not sent: the unit&apos;s reports come unasked, in a form the manuals do not give, and would be taken for replies</source>
        <translation>Y+ se neposílá: hlášení jednotky přicházejí bez vyžádání, ve tvaru, který manuály neuvádějí, a byla by považována za odpovědi</translation>
    </message>
    <message>
        <source>Use Y&amp; (the MPG on, silent); the position is read with P4/PF.</source>
        <translation>Použijte Y&amp; (MPG zapnuto, bez hlášení); poloha se čte příkazy P4/PF.</translation>
    </message>
    <message>
        <source>While the tool is lifted it moves by steps only</source>
        <translation>Se zvednutým nástrojem se pojíždí jen po krocích</translation>
    </message>
    <message>
        <source>Choose a jog step (0.01 to 10 mm) and press the axis button; the tool returns to the lift point before it is lowered.</source>
        <translation>Zvolte krok (0,01 až 10 mm) a stiskněte tlačítko osy; nástroj se před spuštěním vrátí do bodu zvednutí.</translation>
    </message>
    <message>
        <source>%1: %2 got no valid answer (%3%4); gave up after %5 attempts</source>
        <translation>%1: na %2 nepřišla platná odpověď (%3%4); vzdáno po %5 pokusech</translation>
    </message>
    <message>
        <source>Check the cable and that the unit is on, then connect again; a job is kept and continues after the reconnect.</source>
        <translation>Zkontrolujte kabel a zda je jednotka zapnutá, pak se znovu připojte; rozpracovaná úloha zůstává a po připojení pokračuje.</translation>
    </message>
    <message>
        <source>%1: the reply to %2 was lost and the unit&apos;s command index was unknown</source>
        <translation>%1: odpověď na %2 se ztratila a index příkazů jednotky nebyl známý</translation>
    </message>
    <message>
        <source>%1: after %2 the unit&apos;s command index is %3, expected %4 or %5</source>
        <translation>%1: po %2 je index příkazů jednotky %3, očekáván %4 nebo %5</translation>
    </message>
    <message>
        <source>incomplete reply</source>
        <translation>neúplná odpověď</translation>
    </message>
    <message>
        <source>garbled reply</source>
        <translation>poškozená odpověď</translation>
    </message>
    <message>
        <source>doubtful reply</source>
        <translation>nejistá odpověď</translation>
    </message>
    <message>
        <source>garbled reply to &apos;@&apos;</source>
        <translation>poškozená odpověď na &apos;@&apos;</translation>
    </message>
    <message>
        <source>garbled repeated reply</source>
        <translation>poškozená opakovaná odpověď</translation>
    </message>
    <message>
        <source>doubtful repeated reply</source>
        <translation>nejistá opakovaná odpověď</translation>
    </message>
    <message>
        <source>no reply to recovery query</source>
        <translation>žádná odpověď na dotaz obnovy</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>řádek %1</translation>
    </message>
    <message>
        <source>The new feed cannot be set: no speed is planned where the tool stands</source>
        <translation>Nový posuv nelze nastavit: tam, kde nástroj stojí, není naplánovaná žádná rychlost</translation>
    </message>
    <message>
        <source>Lower the tool with the feed unchanged.</source>
        <translation>Spusťte nástroj s nezměněným posuvem.</translation>
    </message>
    <message>
        <source>This unit has no output OUT%1</source>
        <translation>Tato jednotka nemá výstup OUT%1</translation>
    </message>
    <message>
        <source>Switch one of the outputs the unit has (a GVE84 has its relay only).</source>
        <translation>Přepněte některý z výstupů, které jednotka má (GVE84 má jen své relé).</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: address must be 0..7</source>
        <translation>&apos;%1&apos;: adresa musí být 0..7</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 has no address 7 (spindle)</source>
        <translation>&apos;%1&apos;: %2 nemá adresu 7 (vřeteno)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a command of address 7</source>
        <translation>&apos;%1&apos;: takový příkaz adresa 7 nemá</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the spindle speed goes to address 7</source>
        <translation>&apos;%1&apos;: otáčky vřetena patří na adresu 7</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 answers on address 0 only</source>
        <translation>&apos;%1&apos;: %2 odpovídá jen na adrese 0</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 components, %3 takes 3</source>
        <translation>&apos;%1&apos;: %2 složek, %3 bere 3</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 components, %3 takes 3 or 4</source>
        <translation>&apos;%1&apos;: %2 složek, %3 bere 3 nebo 4</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 %3 is outside %4..%5</source>
        <translation>&apos;%1&apos;: %2 %3 je mimo rozsah %4..%5</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: value is not a finite number</source>
        <translation>&apos;%1&apos;: hodnota není konečné číslo</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: travel toward the switch must not be 0</source>
        <translation>&apos;%1&apos;: dráha ke spínači nesmí být 0</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 has no axis %3</source>
        <translation>&apos;%1&apos;: %2 nemá osu %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 has no command %3</source>
        <translation>&apos;%1&apos;: %2 nemá příkaz %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: only C and B belong in a packet</source>
        <translation>&apos;%1&apos;: do paketu patří jen C a B</translation>
    </message>
    <message>
        <source>a packet needs at least one command</source>
        <translation>paket potřebuje aspoň jeden příkaz</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a unit command (it starts with &apos;!&apos; and an address 0..7)</source>
        <translation>&apos;%1&apos;: to není příkaz jednotky (ten začíná znakem &apos;!&apos; a adresou 0..7)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: missing or wrong checksum</source>
        <translation>&apos;%1&apos;: kontrolní součet chybí nebo nesouhlasí</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>neznámý příkaz &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: missing number</source>
        <translation>&apos;%1&apos;: chybí číslo</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: number out of range: %2</source>
        <translation>&apos;%1&apos;: číslo mimo rozsah: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a decimal number: %2</source>
        <translation>&apos;%1&apos;: není desítkové číslo: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a hex byte: %2</source>
        <translation>&apos;%1&apos;: není šestnáctkový bajt: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a number: %2</source>
        <translation>&apos;%1&apos;: není číslo: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: wrong number of parameters</source>
        <translation>&apos;%1&apos;: nesprávný počet parametrů</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: W needs an axis X, Y, Z or A</source>
        <translation>&apos;%1&apos;: W potřebuje osu X, Y, Z nebo A</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: O0 needs &apos;,hh&apos;</source>
        <translation>&apos;%1&apos;: O0 potřebuje &apos;,hh&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: unexpected parameters</source>
        <translation>&apos;%1&apos;: nečekané parametry</translation>
    </message>
    <message>
        <source>component</source>
        <translation>složka</translation>
    </message>
    <message>
        <source>pause (ms)</source>
        <translation>pauza (ms)</translation>
    </message>
    <message>
        <source>SHORT threshold</source>
        <translation>práh SHORT</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>zrychlení</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>rychlost</translation>
    </message>
    <message>
        <source>brake speed</source>
        <translation>brzdná rychlost</translation>
    </message>
    <message>
        <source>multiplier (%)</source>
        <translation>násobitel (%)</translation>
    </message>
    <message>
        <source>counter</source>
        <translation>čítač</translation>
    </message>
    <message>
        <source>travel</source>
        <translation>dráha</translation>
    </message>
    <message>
        <source>speed toward the switch</source>
        <translation>rychlost ke spínači</translation>
    </message>
    <message>
        <source>back-off travel</source>
        <translation>dráha odjezdu ze spínače</translation>
    </message>
    <message>
        <source>speed off the switch</source>
        <translation>rychlost od spínače</translation>
    </message>
    <message>
        <source>EEPROM address</source>
        <translation>adresa v EEPROM</translation>
    </message>
    <message>
        <source>byte</source>
        <translation>bajt</translation>
    </message>
    <message>
        <source>value</source>
        <translation>hodnota</translation>
    </message>
    <message>
        <source>output byte</source>
        <translation>bajt výstupů</translation>
    </message>
    <message>
        <source>status number</source>
        <translation>číslo stavového registru</translation>
    </message>
    <message>
        <source>status byte</source>
        <translation>bajt stavového registru</translation>
    </message>
    <message>
        <source>packet command count</source>
        <translation>počet příkazů paketu</translation>
    </message>
    <message>
        <source>spindle (per mille)</source>
        <translation>vřeteno (promile)</translation>
    </message>
    <message>
        <source>Spindle override %1 % is outside %2 … %3 %</source>
        <translation>Korekce otáček vřetena %1 % je mimo rozsah %2 … %3 %</translation>
    </message>
    <message>
        <source>Choose a spindle override within that range.</source>
        <translation>Zvolte korekci otáček vřetena v tomto rozsahu.</translation>
    </message>
    <message>
        <source>This unit switches its spindle with a relay: its speed cannot be overridden</source>
        <translation>Tato jednotka spíná vřeteno relé: jeho otáčky nelze korigovat</translation>
    </message>
    <message>
        <source>Set the speed on the spindle&apos;s drive, or use a unit with a spindle output at address 7 (GVE64, GVE114).</source>
        <translation>Nastavte otáčky na měniči vřetena, nebo použijte jednotku s výstupem pro vřeteno na adrese 7 (GVE64, GVE114).</translation>
    </message>
</context>
<context>
    <name>frezka::gcode</name>
    <message>
        <source>Cannot read the file %1</source>
        <translation>Soubor %1 nelze přečíst</translation>
    </message>
    <message>
        <source>Check that the file exists and is readable.</source>
        <translation>Zkontrolujte, že soubor existuje a lze jej číst.</translation>
    </message>
    <message>
        <source>Unexpected character &apos;%1&apos;</source>
        <translation>Neočekávaný znak &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Remove it or put it inside a comment ( ).</source>
        <translation>Odstraňte jej nebo jej vložte do komentáře ( ).</translation>
    </message>
    <message>
        <source>Comment is not closed</source>
        <translation>Komentář není uzavřen</translation>
    </message>
    <message>
        <source>Add &apos;)&apos; at the end of the comment.</source>
        <translation>Doplňte &apos;)&apos; na konec komentáře.</translation>
    </message>
    <message>
        <source>Comment inside a comment</source>
        <translation>Komentář uvnitř komentáře</translation>
    </message>
    <message>
        <source>Close the first comment before opening another one.</source>
        <translation>Uzavřete první komentář dříve, než otevřete další.</translation>
    </message>
    <message>
        <source>A number is expected after %1</source>
        <translation>Za %1 se očekává číslo</translation>
    </message>
    <message>
        <source>Write a number, a #parameter or an [expression] after the letter.</source>
        <translation>Za písmeno napište číslo, #parametr nebo [výraz].</translation>
    </message>
    <message>
        <source>%1 needs a whole number</source>
        <translation>%1 vyžaduje celé číslo</translation>
    </message>
    <message>
        <source>Use an integer value here.</source>
        <translation>Zde použijte celočíselnou hodnotu.</translation>
    </message>
    <message>
        <source>Word %1 appears twice in one block</source>
        <translation>Slovo %1 je v jednom bloku dvakrát</translation>
    </message>
    <message>
        <source>Keep one of them or split the block into two lines.</source>
        <translation>Ponechte jen jedno, nebo blok rozdělte na dva řádky.</translation>
    </message>
    <message>
        <source>Word %1 is not supported</source>
        <translation>Slovo %1 není podporováno</translation>
    </message>
    <message>
        <source>Remove the word; Frezka does not use it.</source>
        <translation>Slovo odstraňte, Frezka jej nepoužívá.</translation>
    </message>
    <message>
        <source>Axis %1 is not supported</source>
        <translation>Osa %1 není podporována</translation>
    </message>
    <message>
        <source>Frezka machines have the axes X, Y, Z and A.</source>
        <translation>Stroje Frezka mají osy X, Y, Z a A.</translation>
    </message>
    <message>
        <source>The file ended without M2, M30 or %</source>
        <translation>Soubor skončil bez M2, M30 nebo %</translation>
    </message>
    <message>
        <source>End the program with M2 or M30 (or enclose it in % lines).</source>
        <translation>Ukončete program pomocí M2 nebo M30 (nebo jej uzavřete mezi řádky %).</translation>
    </message>
    <message>
        <source>The program starts with % but has no closing %</source>
        <translation>Program začíná znakem %, ale chybí uzavírací %</translation>
    </message>
    <message>
        <source>Add a line with % at the end of the program.</source>
        <translation>Na konec programu doplňte řádek s %.</translation>
    </message>
    <message>
        <source>Line is too long (%1 characters)</source>
        <translation>Řádek je příliš dlouhý (%1 znaků)</translation>
    </message>
    <message>
        <source>Split the line; at most 65535 characters are allowed.</source>
        <translation>Rozdělte řádek; povoleno je nejvýše 65535 znaků.</translation>
    </message>
    <message>
        <source>Unknown G code %1</source>
        <translation>Neznámý G kód %1</translation>
    </message>
    <message>
        <source>Check the number; see the list of supported codes.</source>
        <translation>Zkontrolujte číslo; viz seznam podporovaných kódů.</translation>
    </message>
    <message>
        <source>%1 is not supported</source>
        <translation>%1 není podporováno</translation>
    </message>
    <message>
        <source>Remove it or post-process the program without it (see the supported codes).</source>
        <translation>Odstraňte jej, nebo program vygenerujte postprocesorem bez něj (viz podporované kódy).</translation>
    </message>
    <message>
        <source>Unknown M code %1</source>
        <translation>Neznámý M kód %1</translation>
    </message>
    <message>
        <source>%1 conflicts with another code of the same group in this block</source>
        <translation>%1 je v tomto bloku v rozporu s jiným kódem téže skupiny</translation>
    </message>
    <message>
        <source>Use one code of each modal group per block.</source>
        <translation>V jednom bloku použijte z každé modální skupiny jen jeden kód.</translation>
    </message>
    <message>
        <source>Too many M codes in one block</source>
        <translation>Příliš mnoho M kódů v jednom bloku</translation>
    </message>
    <message>
        <source>Use at most four M codes per block.</source>
        <translation>V jednom bloku použijte nejvýše čtyři M kódy.</translation>
    </message>
    <message>
        <source>Word %1 is not used by any code in this block</source>
        <translation>Slovo %1 nepoužívá žádný kód v tomto bloku</translation>
    </message>
    <message>
        <source>Remove the word or add the code that uses it.</source>
        <translation>Odstraňte slovo, nebo doplňte kód, který jej používá.</translation>
    </message>
    <message>
        <source>Axis words are given with G80</source>
        <translation>Souřadnice os jsou zadány spolu s G80</translation>
    </message>
    <message>
        <source>G80 cancels the motion mode; give the axis words with G0 or G1.</source>
        <translation>G80 ruší režim pohybu; souřadnice os zadejte s G0 nebo G1.</translation>
    </message>
    <message>
        <source>Axis words are given but no motion mode is active</source>
        <translation>Souřadnice os jsou zadány, ale není aktivní žádný režim pohybu</translation>
    </message>
    <message>
        <source>Add G0, G1, G2 or G3 to the block.</source>
        <translation>Doplňte do bloku G0, G1, G2 nebo G3.</translation>
    </message>
    <message>
        <source>%1 and a motion code both use the axis words</source>
        <translation>%1 i kód pohybu používají souřadnice os</translation>
    </message>
    <message>
        <source>Put them on separate lines.</source>
        <translation>Dejte je na samostatné řádky.</translation>
    </message>
    <message>
        <source>%1 needs at least one axis word</source>
        <translation>%1 vyžaduje alespoň jednu souřadnici osy</translation>
    </message>
    <message>
        <source>Add the axis words (X, Y, Z or A).</source>
        <translation>Doplňte souřadnice os (X, Y, Z nebo A).</translation>
    </message>
    <message>
        <source>%1 must not be negative</source>
        <translation>%1 nesmí být záporné</translation>
    </message>
    <message>
        <source>Use zero or a positive value.</source>
        <translation>Použijte nulu nebo kladnou hodnotu.</translation>
    </message>
    <message>
        <source>G53 needs G0 or G1</source>
        <translation>G53 vyžaduje G0 nebo G1</translation>
    </message>
    <message>
        <source>Write G53 together with G0 or G1 on the same line.</source>
        <translation>Napište G53 spolu s G0 nebo G1 na stejný řádek.</translation>
    </message>
    <message>
        <source>G53 cannot be used in G91 mode</source>
        <translation>G53 nelze použít v režimu G91</translation>
    </message>
    <message>
        <source>Switch to G90 before moving in machine coordinates.</source>
        <translation>Před pohybem ve strojních souřadnicích přepněte na G90.</translation>
    </message>
    <message>
        <source>G4 needs the dwell time P</source>
        <translation>G4 vyžaduje dobu prodlevy P</translation>
    </message>
    <message>
        <source>Add P with the dwell time in seconds.</source>
        <translation>Doplňte P s dobou prodlevy v sekundách.</translation>
    </message>
    <message>
        <source>G10 %1 is not supported</source>
        <translation>G10 %1 není podporováno</translation>
    </message>
    <message>
        <source>G10 needs P0 to P9 (got %1)</source>
        <translation>G10 vyžaduje P0 až P9 (zadáno %1)</translation>
    </message>
    <message>
        <source>P0 is the active coordinate system, P1 to P9 are G54 to G59.3.</source>
        <translation>P0 je aktivní souřadný systém, P1 až P9 jsou G54 až G59.3.</translation>
    </message>
    <message>
        <source>%1 with zero feed rate</source>
        <translation>%1 s nulovým posuvem</translation>
    </message>
    <message>
        <source>Set a feed rate with F before the first feed move.</source>
        <translation>Před prvním pracovním pohybem nastavte posuv pomocí F.</translation>
    </message>
    <message>
        <source>%1 in inverse time mode (G93) needs an F word</source>
        <translation>%1 v režimu inverzního času (G93) vyžaduje slovo F</translation>
    </message>
    <message>
        <source>Give F on every feed move in G93, or switch to G94.</source>
        <translation>V G93 zadejte F u každého pracovního pohybu, nebo přepněte na G94.</translation>
    </message>
    <message>
        <source>Arc without I, J, K or R</source>
        <translation>Oblouk bez I, J, K nebo R</translation>
    </message>
    <message>
        <source>Give the centre with I/J/K or the radius with R.</source>
        <translation>Zadejte střed pomocí I/J/K nebo poloměr pomocí R.</translation>
    </message>
    <message>
        <source>Arc with both R and I/J/K</source>
        <translation>Oblouk zároveň s R i I/J/K</translation>
    </message>
    <message>
        <source>Use either the centre (I/J/K) or the radius (R).</source>
        <translation>Použijte buď střed (I/J/K), nebo poloměr (R).</translation>
    </message>
    <message>
        <source>%1 is not in the arc&apos;s plane</source>
        <translation>%1 neleží v rovině oblouku</translation>
    </message>
    <message>
        <source>G17 uses I and J, G18 uses I and K, G19 uses J and K.</source>
        <translation>G17 používá I a J, G18 I a K, G19 J a K.</translation>
    </message>
    <message>
        <source>%1 is missing for an arc with absolute centre (G90.1)</source>
        <translation>U oblouku s absolutním středem (G90.1) chybí %1</translation>
    </message>
    <message>
        <source>Give both centre coordinates in G90.1 mode.</source>
        <translation>V režimu G90.1 zadejte obě souřadnice středu.</translation>
    </message>
    <message>
        <source>Arc with zero radius %1</source>
        <translation>Oblouk s nulovým poloměrem %1</translation>
    </message>
    <message>
        <source>Check the centre offsets I/J/K.</source>
        <translation>Zkontrolujte vzdálenosti středu I/J/K.</translation>
    </message>
    <message>
        <source>Arc end point is not on the circle: %1</source>
        <translation>Koncový bod oblouku neleží na kružnici: %1</translation>
    </message>
    <message>
        <source>Check the end point and the centre; the radii to start and end must match.</source>
        <translation>Zkontrolujte koncový bod a střed; poloměry k začátku a konci se musí shodovat.</translation>
    </message>
    <message>
        <source>Arc radius is too small to reach the end point %1</source>
        <translation>Poloměr oblouku je příliš malý na dosažení koncového bodu %1</translation>
    </message>
    <message>
        <source>Use a radius of at least half the distance between start and end.</source>
        <translation>Použijte poloměr alespoň poloviny vzdálenosti mezi začátkem a koncem.</translation>
    </message>
    <message>
        <source>Arc given by R ends where it starts</source>
        <translation>Oblouk zadaný pomocí R končí tam, kde začíná</translation>
    </message>
    <message>
        <source>Use I/J/K to program a full circle.</source>
        <translation>Celou kružnici programujte pomocí I/J/K.</translation>
    </message>
    <message>
        <source>Arc given by R has no end point in its plane</source>
        <translation>Oblouk zadaný pomocí R nemá koncový bod ve své rovině</translation>
    </message>
    <message>
        <source>Give the end point, or use I/J/K for a full circle.</source>
        <translation>Zadejte koncový bod, nebo pro celou kružnici použijte I/J/K.</translation>
    </message>
    <message>
        <source>Arc turns P must be a positive integer (got %1)</source>
        <translation>Počet otáček oblouku P musí být kladné celé číslo (zadáno %1)</translation>
    </message>
    <message>
        <source>Use P1 or more, or leave P out.</source>
        <translation>Použijte P1 nebo více, nebo P vynechte.</translation>
    </message>
    <message>
        <source>Probe move does not move</source>
        <translation>Pohyb sondy nikam nevede</translation>
    </message>
    <message>
        <source>Give an end point different from the current position.</source>
        <translation>Zadejte koncový bod odlišný od současné polohy.</translation>
    </message>
    <message>
        <source>Probe move in inverse time mode (G93)</source>
        <translation>Pohyb sondy v režimu inverzního času (G93)</translation>
    </message>
    <message>
        <source>Switch to G94 before probing.</source>
        <translation>Před měřením sondou přepněte na G94.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs R</source>
        <translation>Pevný cyklus %1 vyžaduje R</translation>
    </message>
    <message>
        <source>Give the retract plane R on the first block of the cycle.</source>
        <translation>V prvním bloku cyklu zadejte rovinu návratu R.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs its depth</source>
        <translation>Pevný cyklus %1 vyžaduje hloubku</translation>
    </message>
    <message>
        <source>Give the hole depth (Z in G17) on the first block of the cycle.</source>
        <translation>V prvním bloku cyklu zadejte hloubku díry (Z v G17).</translation>
    </message>
    <message>
        <source>Canned cycle retract plane R is below the hole depth</source>
        <translation>Rovina návratu R pevného cyklu je pod dnem díry</translation>
    </message>
    <message>
        <source>R must be above the bottom of the hole.</source>
        <translation>R musí být nad dnem díry.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs the dwell P</source>
        <translation>Pevný cyklus %1 vyžaduje prodlevu P</translation>
    </message>
    <message>
        <source>Give P (seconds) on the first block of the cycle.</source>
        <translation>V prvním bloku cyklu zadejte P (sekundy).</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs the peck Q</source>
        <translation>Pevný cyklus %1 vyžaduje přírůstek Q</translation>
    </message>
    <message>
        <source>Give Q (peck depth) on the first block of the cycle.</source>
        <translation>V prvním bloku cyklu zadejte Q (hloubku přírůstku).</translation>
    </message>
    <message>
        <source>Peck depth Q must be positive</source>
        <translation>Hloubka přírůstku Q musí být kladná</translation>
    </message>
    <message>
        <source>Use a positive Q.</source>
        <translation>Použijte kladné Q.</translation>
    </message>
    <message>
        <source>Canned cycle repeat L must be a positive integer</source>
        <translation>Počet opakování L pevného cyklu musí být kladné celé číslo</translation>
    </message>
    <message>
        <source>Use L1 or more, or leave L out.</source>
        <translation>Použijte L1 nebo více, nebo L vynechte.</translation>
    </message>
    <message>
        <source>Canned cycle in inverse time mode (G93)</source>
        <translation>Pevný cyklus v režimu inverzního času (G93)</translation>
    </message>
    <message>
        <source>Switch to G94 before a canned cycle.</source>
        <translation>Před pevným cyklem přepněte na G94.</translation>
    </message>
    <message>
        <source>Expression is not closed</source>
        <translation>Výraz není uzavřen</translation>
    </message>
    <message>
        <source>Add the missing &apos;]&apos;.</source>
        <translation>Doplňte chybějící &apos;]&apos;.</translation>
    </message>
    <message>
        <source>Unknown operator %1</source>
        <translation>Neznámý operátor %1</translation>
    </message>
    <message>
        <source>Use + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.</source>
        <translation>Použijte + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.</translation>
    </message>
    <message>
        <source>Unknown function %1</source>
        <translation>Neznámá funkce %1</translation>
    </message>
    <message>
        <source>See the list of functions (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, SIN, SQRT, TAN, EXISTS).</source>
        <translation>Viz seznam funkcí (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, SIN, SQRT, TAN, EXISTS).</translation>
    </message>
    <message>
        <source>Division by zero</source>
        <translation>Dělení nulou</translation>
    </message>
    <message>
        <source>Check the divisor.</source>
        <translation>Zkontrolujte dělitele.</translation>
    </message>
    <message>
        <source>%1 of a value outside its domain</source>
        <translation>%1 z hodnoty mimo definiční obor</translation>
    </message>
    <message>
        <source>Check the argument (e.g. SQRT of a negative number).</source>
        <translation>Zkontrolujte argument (např. SQRT ze záporného čísla).</translation>
    </message>
    <message>
        <source>Negative number raised to a non-integer power</source>
        <translation>Záporné číslo umocněné na neceločíselný exponent</translation>
    </message>
    <message>
        <source>Check the operands of **.</source>
        <translation>Zkontrolujte operandy **.</translation>
    </message>
    <message>
        <source>Parameter number %1 is out of range</source>
        <translation>Číslo parametru %1 je mimo rozsah</translation>
    </message>
    <message>
        <source>Use parameters #1 to #5601.</source>
        <translation>Použijte parametry #1 až #5601.</translation>
    </message>
    <message>
        <source>Parameter %1 is not defined</source>
        <translation>Parametr %1 není definován</translation>
    </message>
    <message>
        <source>Assign it a value before reading it.</source>
        <translation>Před čtením mu přiřaďte hodnotu.</translation>
    </message>
    <message>
        <source>Parameter %1 is read-only</source>
        <translation>Parametr %1 je jen pro čtení</translation>
    </message>
    <message>
        <source>System parameters are set by codes (e.g. G10 L2, G92), not by assignment.</source>
        <translation>Systémové parametry se nastavují kódy (např. G10 L2, G92), ne přiřazením.</translation>
    </message>
    <message>
        <source>Bad parameter name %1</source>
        <translation>Chybný název parametru %1</translation>
    </message>
    <message>
        <source>Write named parameters as #&lt;name&gt;.</source>
        <translation>Pojmenované parametry pište jako #&lt;název&gt;.</translation>
    </message>
    <message>
        <source>An expression is expected %1</source>
        <translation>Očekává se výraz %1</translation>
    </message>
    <message>
        <source>Write the value in brackets, e.g. [#1 + 2].</source>
        <translation>Napište hodnotu do hranatých závorek, např. [#1 + 2].</translation>
    </message>
    <message>
        <source>Malformed O word %1</source>
        <translation>Chybně zapsané slovo O %1</translation>
    </message>
    <message>
        <source>Write O-words as o100 if [...] or o&lt;name&gt; sub.</source>
        <translation>Slova O pište jako o100 if [...] nebo o&lt;název&gt; sub.</translation>
    </message>
    <message>
        <source>Unknown O-word keyword %1</source>
        <translation>Neznámé klíčové slovo O %1</translation>
    </message>
    <message>
        <source>Use sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, break or continue.</source>
        <translation>Použijte sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, break nebo continue.</translation>
    </message>
    <message>
        <source>An O-word line has other words</source>
        <translation>Řádek se slovem O obsahuje další slova</translation>
    </message>
    <message>
        <source>Put the other words on their own line.</source>
        <translation>Ostatní slova dejte na samostatný řádek.</translation>
    </message>
    <message>
        <source>%1 without its opening O-word</source>
        <translation>%1 bez úvodního slova O</translation>
    </message>
    <message>
        <source>Check the O numbers; they must match the opening line.</source>
        <translation>Zkontrolujte čísla O; musí odpovídat úvodnímu řádku.</translation>
    </message>
    <message>
        <source>%1 is never closed</source>
        <translation>%1 není nikde uzavřeno</translation>
    </message>
    <message>
        <source>Add the matching end line (endsub, endif, endwhile, endrepeat or while).</source>
        <translation>Doplňte odpovídající koncový řádek (endsub, endif, endwhile, endrepeat nebo while).</translation>
    </message>
    <message>
        <source>Subroutine %1 is not defined</source>
        <translation>Podprogram %1 není definován</translation>
    </message>
    <message>
        <source>Subroutine calls nested too deeply</source>
        <translation>Volání podprogramů jsou vnořena příliš hluboko</translation>
    </message>
    <message>
        <source>Check for unbounded recursion.</source>
        <translation>Zkontrolujte, zda nejde o nekonečnou rekurzi.</translation>
    </message>
    <message>
        <source>%1 outside a loop with this O number</source>
        <translation>%1 mimo cyklus s tímto číslem O</translation>
    </message>
    <message>
        <source>Use break and continue only inside their own loop.</source>
        <translation>Break a continue používejte jen uvnitř jejich cyklu.</translation>
    </message>
    <message>
        <source>%1 outside a subroutine</source>
        <translation>%1 mimo podprogram</translation>
    </message>
    <message>
        <source>Use return and endsub only inside a subroutine.</source>
        <translation>Return a endsub používejte jen uvnitř podprogramu.</translation>
    </message>
    <message>
        <source>Value of %1 is out of range</source>
        <translation>Hodnota %1 je mimo rozsah</translation>
    </message>
    <message>
        <source>Values must be finite and below 1e12 in size; check the expression.</source>
        <translation>Hodnoty musí být konečné a v absolutní hodnotě menší než 1e12; zkontrolujte výraz.</translation>
    </message>
    <message>
        <source>%1: OK, %2 lines</source>
        <translation>%1: v pořádku, %2 řádků</translation>
    </message>
    <message>
        <source>moves: %1 (rapid %2, feed %3, arc %4, probe %5), dwells: %6</source>
        <translation>pohyby: %1 (rychloposuv %2, posuv %3, oblouk %4, sonda %5), prodlevy: %6</translation>
    </message>
    <message>
        <source>bounds (machine, mm): X %1 .. %2, Y %3 .. %4, Z %5 .. %6, A %7 .. %8</source>
        <translation>rozsah (strojní souřadnice, mm): X %1 .. %2, Y %3 .. %4, Z %5 .. %6, A %7 .. %8</translation>
    </message>
    <message>
        <source>length: rapid %1 mm, feed %2 mm</source>
        <translation>dráha: rychloposuv %1 mm, posuv %2 mm</translation>
    </message>
    <message>
        <source>naive time: %1:%2:%3 (rapid %4 mm/min, no acceleration)</source>
        <translation>hrubý odhad času: %1:%2:%3 (rychloposuv %4 mm/min, bez zrychlení)</translation>
    </message>
    <message>
        <source>usage: frezka-cli toolpath FILE [--events]</source>
        <translation>použití: frezka-cli toolpath SOUBOR [--events]</translation>
    </message>
    <message>
        <source>frezka-cli: cannot write the toolpath</source>
        <translation>frezka-cli: dráhu nástroje nelze zapsat</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n error(s)</source>
        <translation>
            <numerusform>%1: %n chyba</numerusform>
            <numerusform>%1: %n chyby</numerusform>
            <numerusform>%1: %n chyb</numerusform>
        </translation>
    </message>
    <message>
        <source>usage: frezka-cli check FILE [--rapid MM_PER_MIN] %1</source>
        <translation>použití: frezka-cli check SOUBOR [--rapid MM_ZA_MIN] %1</translation>
    </message>
    <message>
        <source>F%1 was read in %2 (line %3) before this change of units: the feed moves after it run at %1 %2 (%4 %5), as in LinuxCNC, not at %1 %5 (%6 %2)</source>
        <translation>F%1 bylo načteno v %2 (řádek %3) před touto změnou jednotek: pracovní posuvy za ní jedou %1 %2 (%4 %5) jako v LinuxCNC, ne %1 %5 (%6 %2)</translation>
    </message>
    <message>
        <source>LinuxCNC reads F before G20/G21, also on the same line; if %1 %5 was meant, give F again after the change of units.</source>
        <translation>LinuxCNC čte F před G20/G21, i na tomtéž řádku; bylo-li míněno %1 %5, zadejte F znovu až po změně jednotek.</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>varování: </translation>
    </message>
    <message>
        <source>note: </source>
        <translation>poznámka: </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n more warning(s) not shown</source>
        <translation>
            <numerusform>%1: %n další varování nezobrazeno</numerusform>
            <numerusform>%1: %n další varování nezobrazena</numerusform>
            <numerusform>%1: %n dalších varování nezobrazeno</numerusform>
        </translation>
    </message>
    <message>
        <source>$H is grbl&apos;s homing command, not G-code</source>
        <translation>$H je příkaz grbl pro najetí do reference, ne G-kód</translation>
    </message>
    <message>
        <source>%1 is a grbl system command, not G-code</source>
        <translation>%1 je systémový příkaz grbl, ne G-kód</translation>
    </message>
    <message>
        <source>Delete the line; grbl&apos;s $ settings and commands have no meaning here (set the machine up in Frezka&apos;s machine profile, home and jog from Frezka).</source>
        <translation>Řádek smažte; nastavení a příkazy $ systému grbl tu nemají význam (stroj nastavte v profilu stroje ve Frezce, referenci a ruční posuvy ovládejte z Frezky).</translation>
    </message>
    <message>
        <source>&apos;//&apos; comments are not RS274/NGC G-code (they come from other controllers&apos; dialects, e.g. Beckhoff TwinCAT)</source>
        <translation>Komentáře &apos;//&apos; nejsou G-kód RS274/NGC (pocházejí z dialektů jiných řídicích systémů, např. Beckhoff TwinCAT)</translation>
    </message>
    <message>
        <source>Write the comment in parentheses ( ) or after a semicolon ;.</source>
        <translation>Napište komentář do kulatých závorek ( ) nebo za středník ;.</translation>
    </message>
    <message>
        <source>M29 is the rigid tapping code of Fanuc-style controllers</source>
        <translation>M29 je kód tuhého řezání závitů řídicích systémů typu Fanuc</translation>
    </message>
    <message>
        <source>Frezka has no spindle-synchronised tapping (the GVE units have no spindle encoder): tap with a floating tap holder or by hand, and post the program without M29 and G84.</source>
        <translation>Frezka neumí řezat závity synchronně s vřetenem (jednotky GVE nemají snímač otáček vřetena): řežte závity v plovoucím držáku nebo ručně a vygenerujte program bez M29 a G84.</translation>
    </message>
    <message>
        <source>The file ends without M2, M30 or %: the program is taken to end here, with the spindle and coolant switched off as at M2</source>
        <translation>Soubor končí bez M2, M30 nebo %: program se považuje za ukončený zde a vřeteno i chlazení se vypnou jako při M2</translation>
    </message>
    <message>
        <source>Check that the file is complete (not cut short when it was copied); end the program with M2 or M30.</source>
        <translation>Zkontrolujte, že je soubor úplný (nebyl při kopírování zkrácen); program ukončete kódem M2 nebo M30.</translation>
    </message>
    <message>
        <source>G4 P%1 dwells %1 seconds (%2), as in LinuxCNC; if the post meant milliseconds (as Mach3 and UCCNC can), that is %3 s</source>
        <translation>G4 P%1 čeká %1 sekund (%2) jako v LinuxCNC; pokud postprocesor myslel milisekundy (jak to umí Mach3 a UCCNC), jde o %3 s</translation>
    </message>
    <message>
        <source>Frezka reads P in seconds; write P%3 if %3 s was meant.</source>
        <translation>Frezka čte P v sekundách; bylo-li míněno %3 s, napište P%3.</translation>
    </message>
    <message>
        <source>%1 has no effect on an arc in the %2 plane and is ignored</source>
        <translation>%1 nemá na oblouk v rovině %2 žádný vliv a přeskakuje se</translation>
    </message>
    <message>
        <source>Some posts (e.g. FreeCAD&apos;s grbl post) write it; LinuxCNC refuses it, and any value other than 0 is an error.</source>
        <translation>Některé postprocesory (např. postprocesor grbl ve FreeCADu) jej zapisují; LinuxCNC jej odmítá a každá jiná hodnota než 0 je chyba.</translation>
    </message>
    <message>
        <source>Home the machine from Frezka (Home all) before starting the program, and delete this line.</source>
        <translation>Před spuštěním programu najeďte strojem do reference z Frezky (Reference všech os) a tento řádek smažte.</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n more error(s) not shown</source>
        <translation>
            <numerusform>%1: %n další chyba nezobrazena</numerusform>
            <numerusform>%1: %n další chyby nezobrazeny</numerusform>
            <numerusform>%1: %n dalších chyb nezobrazeno</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot write the file %1: %2</source>
        <translation>Soubor %1 nelze zapsat: %2</translation>
    </message>
    <message>
        <source>Check that the folder exists and is writable and that the disk is not full; the old file is kept unchanged.</source>
        <translation>Zkontrolujte, že složka existuje, lze do ní zapisovat a disk není plný; původní soubor zůstal beze změny.</translation>
    </message>
    <message>
        <source>Tool table entry cannot be read at &apos;%1&apos;</source>
        <translation>Řádek tabulky nástrojů nelze přečíst u &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Each line is T&lt;tool&gt; P&lt;pocket&gt; with optional X Y Z A B C U V W offsets, D diameter, I J angles and Q orientation (0-9), each letter once, then an optional ; comment, as in LinuxCNC&apos;s .tbl files. Correct the line in Machine &gt; Tool table or in a text editor.</source>
        <translation>Každý řádek je T&lt;nástroj&gt; P&lt;pozice&gt; s volitelnými korekcemi X Y Z A B C U V W, průměrem D, úhly I J a orientací Q (0–9), každé písmeno jednou, a pak volitelný komentář za ; – jako v souborech .tbl systému LinuxCNC. Opravte řádek v Stroj &gt; Tabulka nástrojů nebo v textovém editoru.</translation>
    </message>
    <message>
        <source>Tool %1 is listed twice in the tool table</source>
        <translation>Nástroj %1 je v tabulce nástrojů dvakrát</translation>
    </message>
    <message>
        <source>Keep one line per tool number; delete or renumber the other.</source>
        <translation>Ponechte pro každé číslo nástroje jeden řádek; druhý smažte nebo přečíslujte.</translation>
    </message>
    <message>
        <source>Use G10 L2 or G10 L20 to set a work offset, G10 L1, L10 or L11 to set a tool&apos;s offsets.</source>
        <translation>Posunutí nulového bodu obrobku nastavte pomocí G10 L2 nebo G10 L20, korekce nástroje pomocí G10 L1, L10 nebo L11.</translation>
    </message>
    <message>
        <source>Tool %1 is not in the tool table</source>
        <translation>Nástroj %1 není v tabulce nástrojů</translation>
    </message>
    <message>
        <source>Add the tool with its length and diameter in Machine &gt; Tool table, or correct the T, H or P number.</source>
        <translation>Přidejte nástroj s jeho délkou a průměrem v Stroj &gt; Tabulka nástrojů, nebo opravte číslo T, H či P.</translation>
    </message>
    <message>
        <source>%1 needs either H or axis words, not both or none</source>
        <translation>%1 potřebuje buď H, nebo osová slova, ne obojí ani nic</translation>
    </message>
    <message>
        <source>G43.2 Hn adds tool n&apos;s offsets, G43.2 Z.. adds the given values; G43.1 takes axis words only.</source>
        <translation>G43.2 Hn přičte korekce nástroje n, G43.2 Z.. přičte zadané hodnoty; G43.1 bere jen osová slova.</translation>
    </message>
    <message>
        <source>%1 without offsets has no effect</source>
        <translation>%1 bez korekcí nemá žádný účinek</translation>
    </message>
    <message>
        <source>Give the values to set, e.g. Z for the tool length and R for its radius.</source>
        <translation>Zadejte hodnoty k nastavení, např. Z pro délku nástroje a R pro jeho poloměr.</translation>
    </message>
    <message>
        <source>%1 needs the tool number in %2</source>
        <translation>%1 potřebuje číslo nástroje v %2</translation>
    </message>
    <message>
        <source>Write the number of a tool of the tool table, e.g. M61 Q3 or G10 L1 P3 Z25.</source>
        <translation>Napište číslo nástroje z tabulky nástrojů, např. M61 Q3 nebo G10 L1 P3 Z25.</translation>
    </message>
    <message>
        <source>%1 with tool %2, a lathe tool (orientation %3): the compensation of a lathe tool&apos;s nose radius is not supported</source>
        <translation>%1 s nástrojem %2, soustružnickým nožem (orientace %3): korekce poloměru špičky soustružnického nože není podporována</translation>
    </message>
    <message>
        <source>Give a mill tool orientation 0 in Machine &gt; Tool table, or post the program again from the CAM with the compensation computed there.</source>
        <translation>Frézovacímu nástroji dejte v Stroj &gt; Tabulka nástrojů orientaci 0, nebo vygenerujte program z CAM znovu s korekcí spočtenou v CAM.</translation>
    </message>
    <message>
        <source>%1: cutter radius compensation works only in the XY (G17) and XZ (G18) planes</source>
        <translation>%1: korekce poloměru nástroje funguje jen v rovinách XY (G17) a XZ (G18)</translation>
    </message>
    <message>
        <source>Select G17 or G18 before turning the compensation on.</source>
        <translation>Před zapnutím korekce zvolte G17 nebo G18.</translation>
    </message>
    <message>
        <source>%1 while cutter radius compensation is already on</source>
        <translation>%1, když je korekce poloměru nástroje už zapnutá</translation>
    </message>
    <message>
        <source>Turn it off with G40 first, as LinuxCNC requires.</source>
        <translation>Nejdřív ji vypněte pomocí G40, jak to vyžaduje i LinuxCNC.</translation>
    </message>
    <message>
        <source>%1 is not allowed while cutter radius compensation is on</source>
        <translation>%1 není povoleno, dokud je zapnutá korekce poloměru nástroje</translation>
    </message>
    <message>
        <source>Turn the compensation off with G40 before this block and on again after it, as LinuxCNC requires.</source>
        <translation>Před tímto blokem korekci vypněte pomocí G40 a po něm ji znovu zapněte, jak to vyžaduje i LinuxCNC.</translation>
    </message>
    <message>
        <source>%1 needs D, the diameter of the tool</source>
        <translation>%1 potřebuje D, průměr nástroje</translation>
    </message>
    <message>
        <source>Write the tool&apos;s diameter in D, e.g. %1 D6.</source>
        <translation>Zadejte průměr nástroje v D, např. %1 D6.</translation>
    </message>
    <message>
        <source>The move that starts the cutter radius compensation is not longer than the tool radius (%1)</source>
        <translation>Pohyb, kterým začíná korekce poloměru nástroje, není delší než poloměr nástroje (%1)</translation>
    </message>
    <message>
        <source>Start the compensation from a point farther from the path than the tool radius, e.g. with a lead-in move from outside the part.</source>
        <translation>Začněte korekci z bodu, který je od dráhy dál než poloměr nástroje, např. nájezdem zvenku obrobku.</translation>
    </message>
    <message>
        <source>The tool radius (%1) is not smaller than the radius of this arc, which the tool follows on its inside</source>
        <translation>Poloměr nástroje (%1) není menší než poloměr tohoto oblouku, po jehož vnitřní straně nástroj jede</translation>
    </message>
    <message>
        <source>Use a smaller tool (D), or make the arc larger than the tool.</source>
        <translation>Použijte menší nástroj (D), nebo zvětšete oblouk nad velikost nástroje.</translation>
    </message>
    <message>
        <source>The compensated tool (radius %1) cannot reach this corner without cutting into the part</source>
        <translation>Nástroj s korekcí (poloměr %1) nedosáhne do tohoto rohu, aniž by zařízl do obrobku</translation>
    </message>
    <message>
        <source>Use a smaller tool, or change the path so that the tool fits into the inside corner (LinuxCNC refuses it too).</source>
        <translation>Použijte menší nástroj, nebo upravte dráhu tak, aby se nástroj do vnitřního rohu vešel (LinuxCNC to také odmítne).</translation>
    </message>
    <message>
        <source>The move just after G40 must be straight, not an arc</source>
        <translation>Pohyb hned po G40 musí být přímý, ne oblouk</translation>
    </message>
    <message>
        <source>Add a straight move (G0 or G1) after G40, before the arc.</source>
        <translation>Za G40 a před oblouk vložte přímý pohyb (G0 nebo G1).</translation>
    </message>
    <message>
        <source>%1 with tool %2, whose diameter is 0: the path is not compensated</source>
        <translation>%1 s nástrojem %2, který má průměr 0: dráha se nekoriguje</translation>
    </message>
    <message>
        <source>Enter the tool&apos;s diameter in Machine &gt; Tool table; as it is, the tool follows the programmed path, off the part&apos;s contour by its radius.</source>
        <translation>Zadejte průměr nástroje v Stroj &gt; Tabulka nástrojů; takto nástroj jede po programované dráze, mimo obrys dílu o svůj poloměr.</translation>
    </message>
    <message>
        <source>Polar coordinates (@ radius, ^ angle) cannot be used here (%1)</source>
        <translation>Polární souřadnice (@ poloměr, ^ úhel) zde nelze použít (%1)</translation>
    </message>
    <message>
        <source>Use @ and ^ only in the XY plane (G17), without X and Y words and without G53; at X0 Y0 give the angle ^ with an absolute radius @ (G90).</source>
        <translation>Používejte @ a ^ jen v rovině XY (G17), bez slov X a Y a bez G53; v bodě X0 Y0 zadejte úhel ^ spolu s absolutním poloměrem @ (G90).</translation>
    </message>
    <message>
        <source>The program has executed %1 lines and has not ended; it was stopped here</source>
        <translation>Program vykonal %1 řádků a neskončil; byl zastaven zde</translation>
    </message>
    <message>
        <source>If the program is really this long, raise the machine profile&apos;s program.maxLinesExecuted (Settings › Machine profile › Program).</source>
        <translation>Je-li program opravdu tak dlouhý, zvyšte v profilu stroje program.maxLinesExecuted (Nastavení › Profil stroje › Program).</translation>
    </message>
    <message>
        <source>The program has made %1 moves and has not ended; it was stopped here</source>
        <translation>Program vykonal %1 pohybů a neskončil; byl zastaven zde</translation>
    </message>
    <message>
        <source>If the program really has more moves, raise the machine profile&apos;s program.maxMoves (Settings › Machine profile › Program); a million moves take about 50 MB of memory to check, more to plan and show.</source>
        <translation>Má-li program opravdu více pohybů, zvyšte v profilu stroje program.maxMoves (Nastavení › Profil stroje › Program); milion pohybů zabere při kontrole asi 50 MB paměti, při plánování a zobrazení více.</translation>
    </message>
    <message>
        <source>%3 has not ended after %1 lines executed (it was stopped at line %2)</source>
        <translation>%3 neskončil ani po %1 vykonaných řádcích (zastaven na řádku %2)</translation>
    </message>
    <message>
        <source>Check what ends it (its condition, its count, the exit of a recursion); if it is meant to run this long, raise the machine profile&apos;s program.maxLinesExecuted (Settings › Machine profile › Program).</source>
        <translation>Zkontrolujte, co jej ukončí (podmínku, počet opakování, výstup z rekurze); má-li opravdu běžet tak dlouho, zvyšte v profilu stroje program.maxLinesExecuted (Nastavení › Profil stroje › Program).</translation>
    </message>
    <message>
        <source>%3 has not ended after %1 moves (it was stopped at line %2)</source>
        <translation>%3 neskončil ani po %1 pohybech (zastaven na řádku %2)</translation>
    </message>
    <message>
        <source>Check what ends it (its condition, its count, the exit of a recursion); if it is meant to make more moves, raise the machine profile&apos;s program.maxMoves (Settings › Machine profile › Program).</source>
        <translation>Zkontrolujte, co jej ukončí (podmínku, počet opakování, výstup z rekurze); má-li opravdu vykonat více pohybů, zvyšte v profilu stroje program.maxMoves (Nastavení › Profil stroje › Program).</translation>
    </message>
    <message>
        <source>The program aborts here: %1</source>
        <translation>Program zde končí (abort): %1</translation>
    </message>
    <message>
        <source>An (abort, ...) comment ends the program, as in LinuxCNC. Change the program so that it does not reach this line.</source>
        <translation>Komentář (abort, ...) ukončí program, stejně jako v LinuxCNC. Upravte program tak, aby na tento řádek nedošel.</translation>
    </message>
    <message>
        <source>%1 is not supported under a coordinate system rotation (G10 L2 R)</source>
        <translation>%1 není podporováno při natočení souřadného systému (G10 L2 R)</translation>
    </message>
    <message>
        <source>Arcs outside G17 and cutter radius compensation need the rotation off: set R0 (G10 L2 P0 R0) for that part, or rotate the part in the CAM.</source>
        <translation>Oblouky mimo G17 a korekce poloměru nástroje vyžadují vypnuté natočení: pro tuto část nastavte R0 (G10 L2 P0 R0), nebo díl natočte v CAM.</translation>
    </message>
    <message>
        <source>%1 shares its line with other words</source>
        <translation>%1 sdílí řádek s dalšími slovy</translation>
    </message>
    <message>
        <source>Put M70, M71, M72 and M73 on a line of their own (LinuxCNC runs them in the middle of the line&apos;s other codes).</source>
        <translation>Napište M70, M71, M72 a M73 každé na samostatný řádek (LinuxCNC je provádí uprostřed ostatních kódů řádku).</translation>
    </message>
    <message>
        <source>%1 restores a state that was not saved at this level</source>
        <translation>%1 obnovuje stav, který na této úrovni nebyl uložen</translation>
    </message>
    <message>
        <source>Save the modal state with M70 (or M73) in the same subroutine, or at the top level, before M72, and do not invalidate it with M71 in between.</source>
        <translation>Uložte modální stav pomocí M70 (nebo M73) ve stejném podprogramu, nebo na nejvyšší úrovni, před M72, a mezitím jej nezneplatňujte pomocí M71.</translation>
    </message>
    <message>
        <source>Define it in this file with o&lt;name&gt; sub ... o&lt;name&gt; endsub, or in a file name.ngc beside the program or in a folder of the machine profile&apos;s program.subroutinePath (Settings › Machine profile › Program).</source>
        <translation>Definujte jej v tomto souboru pomocí o&lt;název&gt; sub ... o&lt;název&gt; endsub, nebo v souboru název.ngc vedle programu či ve složce z program.subroutinePath v profilu stroje (Nastavení › Profil stroje › Program).</translation>
    </message>
    <message>
        <source>This INI line is not [SECTION] nor NAME = VALUE: %1</source>
        <translation>Tento řádek INI není [SEKCE] ani NÁZEV = HODNOTA: %1</translation>
    </message>
    <message>
        <source>Fix the line or make it a comment (starting with # or ;).</source>
        <translation>Opravte řádek, nebo z něj udělejte komentář (začínající # nebo ;).</translation>
    </message>
    <message>
        <source>%1 sub is defined inside the running subroutine %2</source>
        <translation>%1 sub je definován uvnitř právě běžícího podprogramu %2</translation>
    </message>
    <message>
        <source>Move the definition out of %2: define it before or after it (in its own file name.ngc when %2 is in a file), as LinuxCNC requires.</source>
        <translation>Přesuňte definici ven z %2: definujte ji před ním nebo za ním (v samostatném souboru název.ngc, je-li %2 v souboru), jak to vyžaduje LinuxCNC.</translation>
    </message>
    <message>
        <source>Subroutine %1 is not defined yet and there is no file %2 on the subroutine path</source>
        <translation>Podprogram %1 zatím není definován a na cestě podprogramů není soubor %2</translation>
    </message>
    <message>
        <source>A subroutine file holds only its own subroutine (as in LinuxCNC): put %1 in a file %2 beside the program or in a folder of the machine profile&apos;s program.subroutinePath, or define it in the program.</source>
        <translation>Soubor podprogramu obsahuje jen svůj vlastní podprogram (jako v LinuxCNC): dejte %1 do souboru %2 vedle programu nebo do složky z program.subroutinePath v profilu stroje, nebo jej definujte v programu.</translation>
    </message>
    <message>
        <source>The file %2 has no line %1 sub</source>
        <translation>Soubor %2 nemá řádek %1 sub</translation>
    </message>
    <message>
        <source>A file name.ngc found for o&lt;name&gt; call must define o&lt;name&gt; sub ... o&lt;name&gt; endsub; rename the file or fix its sub line.</source>
        <translation>Soubor název.ngc nalezený pro o&lt;název&gt; call musí definovat o&lt;název&gt; sub ... o&lt;název&gt; endsub; soubor přejmenujte, nebo opravte jeho řádek sub.</translation>
    </message>
    <message>
        <source>%1: splines work only in the XY plane (G17)</source>
        <translation>%1: spline funguje jen v rovině XY (G17)</translation>
    </message>
    <message>
        <source>Select G17 before the spline, as LinuxCNC requires, or re-post the curve as arcs or lines in its plane.</source>
        <translation>Před spline zvolte G17, jak to vyžaduje LinuxCNC, nebo křivku nechte v CAM znovu vygenerovat jako oblouky či úsečky v její rovině.</translation>
    </message>
    <message>
        <source>%1 cannot move %2: a spline moves X and Y only</source>
        <translation>%1 nemůže pohybovat osou %2: spline pohybuje jen X a Y</translation>
    </message>
    <message>
        <source>Move Z or A in a G1 block of its own before or after the spline.</source>
        <translation>Pohyb Z nebo A zadejte v samostatném bloku G1 před spline nebo za ním.</translation>
    </message>
    <message>
        <source>%1 needs %2</source>
        <translation>%1 potřebuje %2</translation>
    </message>
    <message>
        <source>G5.1 X Y I J: I J is the control point, relative to the start. G5 X Y I J P Q: I J is the first control point, relative to the start (leave both out after a G5 to continue it smoothly), P Q the second, relative to the end.</source>
        <translation>G5.1 X Y I J: I J je řídicí bod, vztažený k začátku. G5 X Y I J P Q: I J je první řídicí bod, vztažený k začátku (po G5 je obě můžete vynechat a křivka plynule naváže), P Q druhý, vztažený ke konci.</translation>
    </message>
    <message>
        <source>A NURBS control point needs both X and Y (%1)</source>
        <translation>Řídicí bod NURBS potřebuje X i Y (%1)</translation>
    </message>
    <message>
        <source>Give X, Y and the weight P on every line from G5.2 to G5.3; P alone is allowed only on the G5.2 line, as the start point&apos;s weight.</source>
        <translation>Na každém řádku od G5.2 do G5.3 zadejte X, Y a váhu P; samotné P je dovoleno jen na řádku G5.2, jako váha počátečního bodu.</translation>
    </message>
    <message>
        <source>NURBS order L%1 is not supported</source>
        <translation>Řád NURBS L%1 není podporován</translation>
    </message>
    <message>
        <source>Give a whole L from 3 (quadratic, also when L is left out) to 10; L4 is cubic.</source>
        <translation>Zadejte celé L od 3 (kvadratická, platí i bez L) do 10; L4 je kubická.</translation>
    </message>
    <message>
        <source>The NURBS has %1 control points, fewer than its order L%2</source>
        <translation>NURBS má %1 řídicích bodů, méně než je její řád L%2</translation>
    </message>
    <message>
        <source>Give at least as many control points (the start point counts) as the order L before G5.3, or a lower L.</source>
        <translation>Před G5.3 zadejte alespoň tolik řídicích bodů (počáteční bod se počítá), kolik je řád L, nebo zadejte nižší L.</translation>
    </message>
    <message>
        <source>G5.3 without G5.2 first</source>
        <translation>G5.3 bez předchozího G5.2</translation>
    </message>
    <message>
        <source>Start the control points with G5.2 X Y P L, or remove this G5.3.</source>
        <translation>Řídicí body začněte pomocí G5.2 X Y P L, nebo toto G5.3 odstraňte.</translation>
    </message>
    <message>
        <source>The NURBS started on line %1 is not ended by G5.3</source>
        <translation>NURBS začatá na řádku %1 není ukončena pomocí G5.3</translation>
    </message>
    <message>
        <source>End its control points with G5.3 before another motion or the program end (LinuxCNC would drop the curve without cutting it).</source>
        <translation>Její řídicí body ukončete pomocí G5.3 před dalším pohybem nebo koncem programu (LinuxCNC by křivku zahodil a neobrobil).</translation>
    </message>
    <message>
        <source>%1 in the block of G5.3</source>
        <translation>%1 v bloku s G5.3</translation>
    </message>
    <message>
        <source>Between G5.2 and G5.3 only further G5.2 control points may come; put other motions on a line of their own after G5.3.</source>
        <translation>Mezi G5.2 a G5.3 smějí být jen další řídicí body G5.2; ostatní pohyby napište na samostatný řádek za G5.3.</translation>
    </message>
    <message>
        <source>A G5.2 NURBS in inverse time mode (G93)</source>
        <translation>NURBS G5.2 v režimu inverzního času (G93)</translation>
    </message>
    <message>
        <source>Switch to G94 and give the feed with F before G5.2 (LinuxCNC does not define how long a NURBS takes in G93).</source>
        <translation>Přepněte na G94 a před G5.2 zadejte posuv pomocí F (LinuxCNC neurčuje, jak dlouho NURBS v G93 trvá).</translation>
    </message>
    <message>
        <source>A NURBS control point needs a weight P from 0.000001 to 1000000 (%1)</source>
        <translation>Řídicí bod NURBS potřebuje váhu P od 0.000001 do 1000000 (%1)</translation>
    </message>
    <message>
        <source>Give P on every control point (P1 for an ordinary B-spline point; LinuxCNC takes -1 when it is missing).</source>
        <translation>Zadejte P u každého řídicího bodu (P1 pro běžný bod B-spline; LinuxCNC chybějící váhu bere jako -1).</translation>
    </message>
</context>
<context>
    <name>frezka::gcode::HeightMap</name>
    <message>
        <source>Height map line %1: unknown key &apos;%2&apos;. Use the keys of docs/height-map.md or make the line a plain comment without a colon.</source>
        <translation>Výšková mapa, řádek %1: neznámý klíč &apos;%2&apos;. Použijte klíče z docs/height-map.md, nebo z řádku udělejte prostý komentář bez dvojtečky.</translation>
    </message>
    <message>
        <source>Height map line %1: &apos;%2&apos; is not a number. Write it as a number in millimetres, such as 10 or -0.25.</source>
        <translation>Výšková mapa, řádek %1: &apos;%2&apos; není číslo. Zapište ho jako číslo v milimetrech, např. 10 nebo -0.25.</translation>
    </message>
    <message>
        <source>The height map lacks a grid key. Its header needs origin_x_mm, origin_y_mm, spacing_x_mm, spacing_y_mm, count_x and count_y.</source>
        <translation>Výškové mapě chybí klíč mřížky. Její hlavička potřebuje origin_x_mm, origin_y_mm, spacing_x_mm, spacing_y_mm, count_x a count_y.</translation>
    </message>
    <message>
        <source>The height map&apos;s grid is not usable: the spacings must be above 0 and the counts whole numbers of at least 2 (at most a million points). Probe the grid again or correct the header.</source>
        <translation>Mřížku výškové mapy nelze použít: rozteče musí být větší než 0 a počty celá čísla alespoň 2 (nejvýše milion bodů). Změřte mřížku znovu nebo opravte hlavičku.</translation>
    </message>
    <message>
        <source>Height map line 1: not a height map of version %1 (the first line must be &apos;# frezka-height-map %1&apos;). Probe the grid again with this version of Frezka.</source>
        <translation>Výšková mapa, řádek 1: není to výšková mapa verze %1 (první řádek musí být &apos;# frezka-height-map %1&apos;). Změřte mřížku znovu touto verzí Frezky.</translation>
    </message>
    <message>
        <source>Height map line %1: a header line after the first row. Move it above the rows.</source>
        <translation>Výšková mapa, řádek %1: řádek hlavičky za prvním řádkem dat. Přesuňte ho nad data.</translation>
    </message>
    <message>
        <source>Height map line %1: expected three numbers X,Y,Z separated by commas. Correct the row or probe the grid again.</source>
        <translation>Výšková mapa, řádek %1: očekávána tři čísla X,Y,Z oddělená čárkami. Opravte řádek nebo změřte mřížku znovu.</translation>
    </message>
    <message>
        <source>Height map line %1: X %2, Y %3 is not a point of the grid in the header. Correct the row or the header.</source>
        <translation>Výšková mapa, řádek %1: X %2, Y %3 není bodem mřížky z hlavičky. Opravte řádek nebo hlavičku.</translation>
    </message>
    <message>
        <source>Height map line %1: the point X %2, Y %3 is given twice. Remove one of the rows.</source>
        <translation>Výšková mapa, řádek %1: bod X %2, Y %3 je uveden dvakrát. Jeden z řádků odstraňte.</translation>
    </message>
    <message>
        <source>The height map has no row for X %1, Y %2. Every point of the grid needs one; probe the grid again.</source>
        <translation>Výšková mapa nemá řádek pro X %1, Y %2. Každý bod mřížky ho potřebuje; změřte mřížku znovu.</translation>
    </message>
    <message>
        <source>Cannot write the height map %1: %2. Choose a folder you may write to.</source>
        <translation>Výškovou mapu %1 nelze zapsat: %2. Zvolte složku, do které smíte zapisovat.</translation>
    </message>
    <message>
        <source>Cannot read the height map %1: %2. Check that the file exists and is readable.</source>
        <translation>Výškovou mapu %1 nelze přečíst: %2. Zkontrolujte, že soubor existuje a je čitelný.</translation>
    </message>
    <message>
        <source>Line %1 cuts at X %2, Y %3, outside the height map (X %4 to %5, Y %6 to %7). Probe a grid that covers the whole program, or run it without the height map.</source>
        <translation>Řádek %1 řeže v X %2, Y %3, mimo výškovou mapu (X %4 až %5, Y %6 až %7). Změřte mřížku, která pokryje celý program, nebo ho spusťte bez výškové mapy.</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::EmulatorTransport</name>
    <message>
        <source>The emulator is not open</source>
        <translation>Emulátor není otevřen</translation>
    </message>
    <message>
        <source>emulator</source>
        <translation>emulátor</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::SerialTransport</name>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 nelze otevřít: %2</translation>
    </message>
    <message>
        <source>Cannot set %1 to %2 Bd: %3</source>
        <translation>%1 nelze nastavit na %2 Bd: %3</translation>
    </message>
    <message>
        <source>%1 is not open</source>
        <translation>%1 není otevřen</translation>
    </message>
    <message>
        <source>Short write on %1: %2 of %3 bytes queued (%4)</source>
        <translation>Neúplný zápis na %1: zařazeno %2 z %3 bajtů (%4)</translation>
    </message>
    <message>
        <source>Serial port %1: %2</source>
        <translation>Sériový port %1: %2</translation>
    </message>
    <message>
        <source>Cannot open %1: permission denied. The port belongs to the group %2: join it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again.</source>
        <translation>%1 nelze otevřít: přístup odepřen. Port patří skupině %2: přidejte se do ní příkazem &quot;sudo usermod -aG %2 $USER&quot;, pak se odhlaste a znovu přihlaste.</translation>
    </message>
    <message>
        <source>%1 (process %2)</source>
        <translation>%1 (proces %2)</translation>
    </message>
    <message>
        <source>another program</source>
        <translation>jiný program</translation>
    </message>
    <message>
        <source>Cannot open %1: the port is in use by another program. Close it (or disconnect it), then connect again.</source>
        <translation>Nelze otevřít %1: port používá jiný program. Zavřete ho (nebo ho v něm odpojte) a připojte se znovu.</translation>
    </message>
    <message>
        <source>Cannot open %1: the port is in use by %2. Close that program (or disconnect it there), then connect again.</source>
        <translation>Nelze otevřít %1: port používá %2. Zavřete ten program (nebo port v něm odpojte) a připojte se znovu.</translation>
    </message>
    <message>
        <source>The port %1 went away: is the cable or the USB adapter unplugged? Plug it in, then connect again.</source>
        <translation>Port %1 zmizel: není odpojený kabel nebo USB převodník? Zapojte ho a připojte se znovu.</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::TransferSession</name>
    <message>
        <source>The port %1 is not open.</source>
        <translation>Port %1 není otevřen.</translation>
    </message>
    <message>
        <source>The data are too long for one message: %1 bytes, at most %2.</source>
        <translation>Data jsou na jednu zprávu příliš dlouhá: %1 bajtů, nejvýše %2.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Zrušeno.</translation>
    </message>
    <message>
        <source>&lt;- noise, %1 bytes skipped: %2</source>
        <translation>&lt;- šum, přeskočeno %1 bajtů: %2</translation>
    </message>
    <message>
        <source>Unexpected reply %1 to %2.</source>
        <translation>Neočekávaná odpověď %1 na %2.</translation>
    </message>
    <message>
        <source>The controller answered NAK to ENQ.</source>
        <translation>Řídicí systém odpověděl na ENQ zápornou odpovědí NAK.</translation>
    </message>
    <message>
        <source>The controller answered NAK to %1: is it set to program transfer (KONFIG6) with the selector in PGN?</source>
        <translation>Řídicí systém odpověděl na %1 zápornou odpovědí NAK: je nastaven na přenos programů (KONFIG6) a přepínač v poloze PGN?</translation>
    </message>
    <message>
        <source>The controller answered NAK to %1 (%2 times): it did not accept the data.</source>
        <translation>Řídicí systém odpověděl na %1 zápornou odpovědí NAK (%2krát): data nepřijal.</translation>
    </message>
    <message>
        <source>&lt;- %1 ignored: no reply expected now</source>
        <translation>&lt;- %1 přeskočeno: žádná odpověď se teď nečeká</translation>
    </message>
    <message>
        <source>Bad checksum in %1 from the controller: received %2, computed %3.</source>
        <translation>Chybný kontrolní součet v %1 od řídicího systému: přijato %2, vypočteno %3.</translation>
    </message>
    <message>
        <source>%1 Given up after %2 repeats.</source>
        <translation>%1 Vzdáno po %2 opakováních.</translation>
    </message>
    <message>
        <source>Repeat %1 of %2: %3</source>
        <translation>Opakování %1 z %2: %3</translation>
    </message>
    <message>
        <source>The data message stopped after %1 of %2 bytes (no byte for %3 s).</source>
        <translation>Datová zpráva se zastavila po %1 z %2 bajtů (%3 s nepřišel žádný bajt).</translation>
    </message>
    <message>
        <source>No data from the controller within %1 s after %2.</source>
        <translation>Řídicí systém neposlal do %1 s po %2 žádná data.</translation>
    </message>
    <message>
        <source>No ACK to %1 within %2 s after its last byte.</source>
        <translation>Na %1 nepřišlo do %2 s po posledním bajtu potvrzení ACK.</translation>
    </message>
    <message>
        <source>The final ACK could not be sent within %1 s.</source>
        <translation>Závěrečné potvrzení ACK se nepodařilo odeslat do %1 s.</translation>
    </message>
    <message>
        <source>Connected.</source>
        <translation>Připojeno.</translation>
    </message>
    <message>
        <source>Received %1 bytes, header &quot;%2&quot;.</source>
        <translation>Přijato %1 bajtů, hlavička „%2“.</translation>
    </message>
    <message>
        <source>Sent %1 bytes; the controller stored them.</source>
        <translation>Odesláno %1 bajtů, řídicí systém je uložil.</translation>
    </message>
    <message>
        <source>no inner blocks (%1 bytes)</source>
        <translation>žádné vnitřní bloky (%1 bajtů)</translation>
    </message>
    <message>
        <source>%1 blocks, all valid</source>
        <translation>%1 bloků, všechny v pořádku</translation>
    </message>
    <message>
        <source>%1 (no AA)</source>
        <translation>%1 (chybí AA)</translation>
    </message>
    <message>
        <source>%1 (wrong block id)</source>
        <translation>%1 (chybné číslo bloku)</translation>
    </message>
    <message>
        <source>%1 (checksum)</source>
        <translation>%1 (kontrolní součet)</translation>
    </message>
    <message>
        <source>%1 of %2 blocks invalid: %3 (the data are kept unchanged)</source>
        <translation>%1 z %2 bloků je chybných: %3 (data zůstávají beze změny)</translation>
    </message>
    <message>
        <source>&lt;- ACK ignored: a late answer to an earlier message</source>
        <translation>&lt;- ACK přeskočeno: opožděná odpověď na dřívější zprávu</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Upozornění: %1</translation>
    </message>
    <message>
        <source>The controller may still be sending its data for about %1 s; the link check waits until then.</source>
        <translation>Řídicí systém může ještě asi %1 s posílat svá data; kontrola spojení do té doby počká.</translation>
    </message>
    <message>
        <source>The controller received only part of the data and discards it; the programs it holds are unchanged.</source>
        <translation>Řídicí systém dostal jen část dat a zahodí je; programy, které má uložené, zůstávají beze změny.</translation>
    </message>
    <message>
        <source>All data had been sent: the controller may have stored them. Check its programs.</source>
        <translation>Všechna data už byla odeslána: řídicí systém je možná uložil. Zkontrolujte jeho programy.</translation>
    </message>
    <message>
        <source>The controller answered NAK to %1: is the ANC set up for program transfer and not grinding?</source>
        <translation>Řídicí systém odpověděl NAK na %1: je ANC nastaven na přenos programů a nebrousí?</translation>
    </message>
    <message>
        <source>The controller&apos;s reply does not fit the %1 messages: is the wrong system selected (ANC or K51)? Choose the system the control is, then try again. (%2)</source>
        <translation>Odpověď řídicího systému neodpovídá zprávám %1: není vybrán nesprávný systém (ANC nebo K51)? Vyberte systém, kterým řídicí systém je, a zkuste to znovu. (%2)</translation>
    </message>
    <message>
        <source>The port %1 stopped taking data: %2 bytes of %3 were not sent. Check that the cable and the USB adapter are plugged in.</source>
        <translation>Port %1 přestal přijímat data: %2 bajtů zprávy %3 se neodeslalo. Zkontrolujte, že jsou kabel i USB převodník zapojené.</translation>
    </message>
    <message>
        <source>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd), the selected system (ANC) and that the ANC is not grinding.</source>
        <translation>Žádná odpověď na ENQ do %1 s. Zkontrolujte kabel, nastavení linky (%2 Bd), vybraný systém (ANC) a že ANC nebrousí.</translation>
    </message>
    <message>
        <source>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd), the selected system (%3) and that the controller is set to transfer (KONFIG6).</source>
        <translation>Žádná odpověď na ENQ do %1 s. Zkontrolujte kabel, nastavení linky (%2 Bd), vybraný systém (%3) a že je řídicí systém nastaven na přenos (KONFIG6).</translation>
    </message>
    <message>
        <source>A table goes only from the PC to the controller (as APROXTAB sent it); there is nothing to receive. Choose K51 programs to receive programs.</source>
        <translation>Tabulka jde jen z PC do řídicího systému (jak ji posílal APROXTAB); není co přijmout. Chcete-li přijmout programy, zvolte programy K51.</translation>
    </message>
    <message>
        <source>Is it set to program transfer (KONFIG6 = 2)? Set to table transfer (KONFIG6 = 3) it refuses programs.</source>
        <translation>Je nastaven na přenos programů (KONFIG6 = 2)? Nastavený na přenos tabulky (KONFIG6 = 3) programy odmítá.</translation>
    </message>
    <message>
        <source>Is it set to table transfer (KONFIG6 = 3)? Only then does it take a table.</source>
        <translation>Je nastaven na přenos tabulky (KONFIG6 = 3)? Jen tak tabulku přijme.</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::ZLinkSession</name>
    <message>
        <source>No answer to &quot;%1&quot; within %2 s. Is the controller set to Z-position transfer (KONFIG6 = 1) with the selector in PGN?</source>
        <translation>Na „%1“ nepřišla do %2 s odpověď. Je řídicí systém nastaven na přenos polohy Z (KONFIG6 = 1) a přepínač v poloze PGN?</translation>
    </message>
    <message>
        <source>The controller rejected a character of &quot;%1&quot; (%2).</source>
        <translation>Řídicí systém odmítl znak z „%1“ (%2).</translation>
    </message>
    <message>
        <source>Unreadable reply &quot;%1&quot;.</source>
        <translation>Nečitelná odpověď „%1“.</translation>
    </message>
</context>
<context>
    <name>frezka::gui</name>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>spindle</source>
        <translation>vřeteno</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>nepoužito</translation>
    </message>
    <message>
        <source>laser</source>
        <translation>laser</translation>
    </message>
    <message>
        <source>coolant</source>
        <translation>chlazení</translation>
    </message>
    <message>
        <source>air blow</source>
        <translation>ofuk</translation>
    </message>
    <message>
        <source>machine cover lock</source>
        <translation>zámek krytu stroje</translation>
    </message>
    <message>
        <source>tool release</source>
        <translation>uvolnění nástroje</translation>
    </message>
    <message>
        <source>tool cover open</source>
        <translation>otevření krytu nástrojů</translation>
    </message>
    <message>
        <source>brake</source>
        <translation>brzda</translation>
    </message>
    <message>
        <source>interrupt signal</source>
        <translation>signalizace přerušení</translation>
    </message>
    <message>
        <source>Lower limit %1</source>
        <translation>Spodní limit %1</translation>
    </message>
    <message>
        <source>Upper limit %1</source>
        <translation>Horní limit %1</translation>
    </message>
    <message>
        <source>Steps per mm %1</source>
        <translation>Kroků na mm %1</translation>
    </message>
    <message>
        <source>Homing speed %1</source>
        <translation>Rychlost najetí do reference %1</translation>
    </message>
    <message>
        <source>Relay function</source>
        <translation>Funkce relé</translation>
    </message>
    <message>
        <source>OUT1 function</source>
        <translation>Funkce OUT1</translation>
    </message>
    <message>
        <source>OUT2 function</source>
        <translation>Funkce OUT2</translation>
    </message>
    <message>
        <source>OUT3 function</source>
        <translation>Funkce OUT3</translation>
    </message>
    <message>
        <source>PWM mode</source>
        <translation>Režim PWM</translation>
    </message>
    <message>
        <source>STEP/DIR polarity</source>
        <translation>Polarita STEP/DIR</translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation>Ruční kolečko (MPG)</translation>
    </message>
    <message>
        <source>Input that starts homing</source>
        <translation>Vstup spouštějící najetí do reference</translation>
    </message>
    <message>
        <source>Interrupt enable IN0-7</source>
        <translation>Povolení přerušení IN0-7</translation>
    </message>
    <message>
        <source>Interrupt enable IN14/IN15</source>
        <translation>Povolení přerušení IN14/IN15</translation>
    </message>
    <message>
        <source>Input polarity IN0-7</source>
        <translation>Polarita vstupů IN0-7</translation>
    </message>
    <message>
        <source>Input polarity IN14/IN15</source>
        <translation>Polarita vstupů IN14/IN15</translation>
    </message>
    <message>
        <source>A axis coupling</source>
        <translation>Sdružení osy A</translation>
    </message>
    <message>
        <source>Baud range</source>
        <translation>Rozsah přenosových rychlostí</translation>
    </message>
    <message>
        <source>Handwheel acceleration</source>
        <translation>Zrychlení ručního kolečka</translation>
    </message>
    <message>
        <source>Handwheel maximum speed</source>
        <translation>Maximální rychlost ručního kolečka</translation>
    </message>
    <message>
        <source>Handwheel brake delay</source>
        <translation>Prodleva brzdění ručního kolečka</translation>
    </message>
    <message>
        <source>Default spindle speed</source>
        <translation>Výchozí otáčky vřetene</translation>
    </message>
    <message>
        <source>Handwheel step multiplier</source>
        <translation>Násobitel kroku ručního kolečka</translation>
    </message>
    <message>
        <source>Brake release delay</source>
        <translation>Zpoždění odbrždění brzdy</translation>
    </message>
    <message>
        <source>Address 0x%1</source>
        <translation>Adresa 0x%1</translation>
    </message>
    <message>
        <source>%1 steps/mm</source>
        <translation>%1 kroků/mm</translation>
    </message>
    <message>
        <source>homing off</source>
        <translation>reference vypnuta</translation>
    </message>
    <message>
        <source>standard PWM</source>
        <translation>standardní PWM</translation>
    </message>
    <message>
        <source>breakout-board signal (jumper ANA/PWM)</source>
        <translation>signál pro oddělovací desky (propojka ANA/PWM)</translation>
    </message>
    <message>
        <source>unknown (0x%1)</source>
        <translation>neznámé (0x%1)</translation>
    </message>
    <message>
        <source>STEP inverted: %1; DIR inverted: %2</source>
        <translation>STEP obrácen: %1; DIR obrácen: %2</translation>
    </message>
    <message>
        <source>DIR inverted: %1; STEP on %2 edge</source>
        <translation>DIR obrácen: %1; STEP na %2 hraně</translation>
    </message>
    <message>
        <source>falling</source>
        <translation>sestupné</translation>
    </message>
    <message>
        <source>rising</source>
        <translation>náběžné</translation>
    </message>
    <message>
        <source>on</source>
        <translation>zapnuto</translation>
    </message>
    <message>
        <source>on, within the limits</source>
        <translation>zapnuto, v mezích limit</translation>
    </message>
    <message>
        <source>on, 4th position drives rotary A</source>
        <translation>zapnuto, 4. poloha ovládá otočnou osu A</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
    <message>
        <source>on with limits, 4th position drives rotary A</source>
        <translation>zapnuto s limity, 4. poloha ovládá otočnou osu A</translation>
    </message>
    <message>
        <source>IN%1 held &gt; 1 s starts homing</source>
        <translation>IN%1 sepnutý &gt; 1 s spustí najetí do reference</translation>
    </message>
    <message>
        <source>enabled: %1</source>
        <translation>povoleno: %1</translation>
    </message>
    <message>
        <source>active high: %1</source>
        <translation>aktivní v log. 1: %1</translation>
    </message>
    <message>
        <source>slaved to X</source>
        <translation>sdružena s X</translation>
    </message>
    <message>
        <source>slaved to Y</source>
        <translation>sdružena s Y</translation>
    </message>
    <message>
        <source>slaved to Z</source>
        <translation>sdružena se Z</translation>
    </message>
    <message>
        <source>independent</source>
        <translation>samostatná</translation>
    </message>
    <message>
        <source>921 600 / 460 800 / 230 400 / 115 200 Bd</source>
        <translation>921 600 / 460 800 / 230 400 / 115 200 Bd</translation>
    </message>
    <message>
        <source>19 200 / 38 400 / 57 600 / 115 200 Bd</source>
        <translation>19 200 / 38 400 / 57 600 / 115 200 Bd</translation>
    </message>
    <message>
        <source>×%1 (x1 = %2 mm)</source>
        <translation>×%1 (x1 = %2 mm)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::CommissionDialog</name>
    <message>
        <source>Commission this machine</source>
        <translation>Uvést tento stroj do provozu</translation>
    </message>
    <message>
        <source>Start runs the steps that move nothing at once; each step that moves or switches something waits for Run or Skip.</source>
        <translation>Start hned provede kroky, které ničím nepohybují; každý krok, který pohybuje nebo něco spíná, čeká na Provést nebo Přeskočit.</translation>
    </message>
    <message>
        <source>measured mm (empty: as asked)</source>
        <translation>naměřené mm (prázdné: jak bylo zadáno)</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Start</translation>
    </message>
    <message>
        <source>&amp;Run step</source>
        <translation>&amp;Provést krok</translation>
    </message>
    <message>
        <source>S&amp;kip step</source>
        <translation>Př&amp;eskočit krok</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ano</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Ne</translation>
    </message>
    <message>
        <source>&amp;OK</source>
        <translation>&amp;OK</translation>
    </message>
    <message>
        <source>Save &amp;report…</source>
        <translation>Uložit p&amp;rotokol…</translation>
    </message>
    <message>
        <source>Save &amp;profile…</source>
        <translation>Uložit pro&amp;fil…</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Zavřít</translation>
    </message>
    <message>
        <source>Checking the unit (nothing moves)…</source>
        <translation>Kontrola jednotky (nic se nepohybuje)…</translation>
    </message>
    <message>
        <source>the port could not be opened: %1</source>
        <translation>port nelze otevřít: %1</translation>
    </message>
    <message>
        <source>Done. Save the report (and the updated profile, under a new name).</source>
        <translation>Hotovo. Uložte protokol (a upravený profil pod novým jménem).</translation>
    </message>
    <message>
        <source>Save the commissioning report</source>
        <translation>Uložit protokol o uvedení do provozu</translation>
    </message>
    <message>
        <source>Text (*.txt)</source>
        <translation>Text (*.txt)</translation>
    </message>
    <message>
        <source>Save the updated profile under a new name</source>
        <translation>Uložit upravený profil pod novým jménem</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Profily strojů (*.json)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ConsoleWidget</name>
    <message>
        <source>Save log</source>
        <translation>Uložit záznam</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Do %1 nelze zapisovat: %2</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Save log…</source>
        <translation>Uložit záznam…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Odeslat</translation>
    </message>
    <message>
        <source>G-code (e.g. G0 X10) or a raw unit command (e.g. !0PF), Enter sends</source>
        <translation>G-kód (např. G0 X10) nebo přímý příkaz jednotce (např. !0PF), Enter odešle</translation>
    </message>
    <message>
        <source>Polls</source>
        <translation>Dotazy</translation>
    </message>
    <message>
        <source>Also show the periodic position and status polls</source>
        <translation>Zobrazit i pravidelné dotazy na polohu a stav</translation>
    </message>
    <message>
        <source>Serial trace (*.trace)</source>
        <translation>Sériový záznam (*.trace)</translation>
    </message>
    <message>
        <source>Console log as shown (*.txt *.log)</source>
        <translation>Výpis konzole, jak je zobrazen (*.txt *.log)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::DroWidget</name>
    <message>
        <source>Work</source>
        <translation>Obrobek</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Nula</translation>
    </message>
    <message>
        <source>Set the work zero of %1 at the current position</source>
        <translation>Nastavit nulový bod obrobku osy %1 do současné polohy</translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation>Vynulovat vše</translation>
    </message>
    <message>
        <source>Set the work zero of every axis at the current position</source>
        <translation>Nastavit nulový bod obrobku všech os do současné polohy</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Posunutí</translation>
    </message>
    <message>
        <source>≈ modelled between position reads</source>
        <translation>≈ modelováno mezi čteními polohy</translation>
    </message>
    <message>
        <source>While the serial line is busy with a dense job the unit&apos;s counters are read only now and then; in between, the figures follow the driver&apos;s model of the unit along the plan, never ahead of what the unit was sent, and each read corrects them.</source>
        <translation>Když je sériová linka vytížena hustým programem, čítače jednotky se čtou jen občas; mezi čteními údaje sledují model jednotky v ovladači podél plánu, nikdy dál, než kolik bylo jednotce odesláno, a každé čtení je opraví.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::GrinderWindow</name>
    <message>
        <source>Connect</source>
        <translation>Připojit</translation>
    </message>
    <message>
        <source>Grinder transfer</source>
        <translation>Přenos pro brusky</translation>
    </message>
    <message>
        <source>K51 programs (K51LOAD/K51SAVE, KCOMM)</source>
        <translation>Programy K51 (K51LOAD/K51SAVE, KCOMM)</translation>
    </message>
    <message>
        <source>ANC programs (ANCLOAD/ANCSAVE)</source>
        <translation>Programy ANC (ANCLOAD/ANCSAVE)</translation>
    </message>
    <message>
        <source>ANC hard-chrome data (HEDIT)</source>
        <translation>Data tvrdého chromu ANC (HEDIT)</translation>
    </message>
    <message>
        <source>Program transfer</source>
        <translation>Přenos programů</translation>
    </message>
    <message>
        <source>Z position, FORM=1 (ASCII)</source>
        <translation>Poloha Z, FORM=1 (ASCII)</translation>
    </message>
    <message>
        <source>Z position, FORM=2 (binary)</source>
        <translation>Poloha Z, FORM=2 (binárně)</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Připojení</translation>
    </message>
    <message>
        <source>Control:</source>
        <translation>Řídicí systém:</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Režim:</translation>
    </message>
    <message>
        <source>Z position</source>
        <translation>Poloha Z</translation>
    </message>
    <message>
        <source>Serial monitor</source>
        <translation>Monitor sériové linky</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Nepřipojeno.</translation>
    </message>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Nelze se připojit: %1</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Odpojit</translation>
    </message>
    <message>
        <source>Open: %1 at %2 Bd.</source>
        <translation>Otevřeno: %1 při %2 Bd.</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Připojeno</translation>
    </message>
    <message>
        <source>No connection</source>
        <translation>Bez spojení</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>%1 — %2: %3</source>
        <translation>%1 — %2: %3</translation>
    </message>
    <message>
        <source>Disconnected during the transfer.</source>
        <translation>Odpojeno během přenosu.</translation>
    </message>
    <message>
        <source>Waiting for the controller to finish its message (about %1 s)…</source>
        <translation>Čeká se, až řídicí systém dokončí svou zprávu (asi %1 s)…</translation>
    </message>
    <message>
        <source>The data received from the controller have not been saved. Close and discard them?</source>
        <translation>Data přijatá z řídicího systému nejsou uložena. Zavřít okno a zahodit je?</translation>
    </message>
    <message>
        <source>K51 table (APROXTAB), PC → controller only</source>
        <translation>Tabulka K51 (APROXTAB), jen PC → řídicí systém</translation>
    </message>
    <message>
        <source>HEDIT data</source>
        <translation>Data HEDIT</translation>
    </message>
    <message>
        <source>HEDIT editor</source>
        <translation>Editor HEDIT</translation>
    </message>
</context>
<context>
    <name>frezka::gui::HardChromeEditor</name>
    <message>
        <source>Address</source>
        <translation>Adresa</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Decimal</source>
        <translation>Desítkově</translation>
    </message>
    <message>
        <source>Hard-chrome data for parametric plunge and traverse grinding: 0x2E bytes from address 0x1100. The manual does not describe the single values, so each byte is shown as it is; what you do not edit is kept unchanged.</source>
        <translation>Data pro tvrdé chromování pro parametrické zápichové a podélné broušení: 0x2E bajtů od adresy 0x1100. Příručka jednotlivé hodnoty nepopisuje, proto se každý bajt zobrazuje tak, jak je; co neupravíte, zůstane beze změny.</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Otevřít…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Uložit…</translation>
    </message>
    <message>
        <source>Take received data</source>
        <translation>Převzít přijatá data</translation>
    </message>
    <message>
        <source>Send to controller</source>
        <translation>Poslat do řídicího systému</translation>
    </message>
    <message>
        <source>Header:</source>
        <translation>Hlavička:</translation>
    </message>
    <message>
        <source>Frezka grinder file (*.frg);;Bare data (*.bin)</source>
        <translation>Soubor Frezka pro brusky (*.frg);;Holá data (*.bin)</translation>
    </message>
    <message>
        <source>Save HEDIT data</source>
        <translation>Uložit data HEDIT</translation>
    </message>
    <message>
        <source>Open HEDIT data</source>
        <translation>Otevřít data HEDIT</translation>
    </message>
    <message>
        <source>Grinder files (*.frg *.bin);;All files (*)</source>
        <translation>Soubory pro brusky (*.frg *.bin);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>0x%1: &quot;%2&quot; is not a byte in hex (00 to FF); the value is kept.</source>
        <translation>0x%1: „%2“ není bajt v šestnáctkové soustavě (00 až FF); hodnota zůstává.</translation>
    </message>
    <message>
        <source>0x%1 set to %2.</source>
        <translation>0x%1 nastaveno na %2.</translation>
    </message>
    <message>
        <source>HEDIT data have 46 bytes (0x2E); these have %1. Nothing changed.</source>
        <translation>Data HEDIT mají 46 bajtů (0x2E); tato mají %1. Nic se nezměnilo.</translation>
    </message>
    <message>
        <source>46 bytes loaded.</source>
        <translation>Načteno 46 bajtů.</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Nelze číst %1: %2</translation>
    </message>
    <message>
        <source>%1 holds %2 data, not HEDIT data.</source>
        <translation>%1 obsahuje data %2, ne data HEDIT.</translation>
    </message>
    <message>
        <source>%1 is damaged: %2</source>
        <translation>%1 je poškozený: %2</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Nelze zapsat %1: %2</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Uloženo do %1.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::HeightMapDialog</name>
    <message>
        <source>Save height map</source>
        <translation>Uložit výškovou mapu</translation>
    </message>
    <message>
        <source>Height maps (*.csv)</source>
        <translation>Výškové mapy (*.csv)</translation>
    </message>
    <message>
        <source>Load height map</source>
        <translation>Načíst výškovou mapu</translation>
    </message>
    <message>
        <source>Height map</source>
        <translation>Výšková mapa</translation>
    </message>
    <message>
        <source>Area X from / to (mm)</source>
        <translation>Oblast X od / do (mm)</translation>
    </message>
    <message>
        <source>Area Y from / to (mm)</source>
        <translation>Oblast Y od / do (mm)</translation>
    </message>
    <message>
        <source>Spacing (mm)</source>
        <translation>Rozteč (mm)</translation>
    </message>
    <message>
        <source>Clearance above Z 0 (mm)</source>
        <translation>Bezpečná výška nad Z 0 (mm)</translation>
    </message>
    <message>
        <source>Probe depth below Z 0 (mm)</source>
        <translation>Hloubka sondování pod Z 0 (mm)</translation>
    </message>
    <message>
        <source>Probe feed (mm/min)</source>
        <translation>Posuv sondování (mm/min)</translation>
    </message>
    <message>
        <source>Area of the loaded program</source>
        <translation>Oblast načteného programu</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Sondovat</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Uložit…</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Načíst…</translation>
    </message>
    <message>
        <source>Apply to the program</source>
        <translation>Použít na program</translation>
    </message>
    <message>
        <source>Remove from the program</source>
        <translation>Odebrat z programu</translation>
    </message>
    <message>
        <source>On Apply, set the work&apos;s Z zero on the surface at the first point</source>
        <translation>Při použití nastavit nulu Z obrobku na povrch v prvním bodě</translation>
    </message>
    <message>
        <source>Probes the grid with G38.2 at every point (the probe input IN15), back up to the clearance between the points.</source>
        <translation>Sonduje mřížku pomocí G38.2 v každém bodě (vstup sondy IN15), mezi body se vrací do bezpečné výšky.</translation>
    </message>
    <message>
        <source>Probing %1 points…</source>
        <translation>Sondování %1 bodů…</translation>
    </message>
    <message>
        <source>Probed %1 of %2 points.</source>
        <translation>Nasondováno %1 z %2 bodů.</translation>
    </message>
    <message>
        <source>All %1 points probed.</source>
        <translation>Nasondováno všech %1 bodů.</translation>
    </message>
    <message>
        <source>Probing stopped after %1 of %2 points.</source>
        <translation>Sondování se zastavilo po %1 z %2 bodů.</translation>
    </message>
    <message>
        <source>There is no height map to save: probe or load one.</source>
        <translation>Není co uložit: výškovou mapu nejprve nasondujte nebo načtěte.</translation>
    </message>
    <message>
        <source>Height map saved to %1.</source>
        <translation>Výšková mapa uložena do %1.</translation>
    </message>
    <message>
        <source>Height map loaded from %1.</source>
        <translation>Výšková mapa načtena z %1.</translation>
    </message>
    <message>
        <source>%1 x %2 points, heights %3 to %4 mm from the first point (machine Z %5)</source>
        <translation>%1 x %2 bodů, výšky %3 až %4 mm vůči prvnímu bodu (Z stroje %5)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::HoldBanner</name>
    <message>
        <source>at line %1</source>
        <translation>na řádku %1</translation>
    </message>
    <message>
        <source>Paused %1</source>
        <translation>Pozastaveno %1</translation>
    </message>
    <message>
        <source>Program stop %1</source>
        <translation>Zastavení programu %1</translation>
    </message>
    <message>
        <source>%1
Do what the program asks, then press Continue.</source>
        <translation>%1
Udělejte, co program žádá, a stiskněte Pokračovat.</translation>
    </message>
    <message>
        <source>Stopped by an input %1</source>
        <translation>Zastaveno vstupem %1</translation>
    </message>
    <message>
        <source>%1
Check the machine; when it is safe, Continue or Abort.</source>
        <translation>%1
Zkontrolujte stroj; až to bude bezpečné, pokračujte nebo úlohu přerušte.</translation>
    </message>
    <message>
        <source>Probe failed %1</source>
        <translation>Měření sondou selhalo %1</translation>
    </message>
    <message>
        <source>%1
The probe did not touch as expected. Abort the job or Continue.</source>
        <translation>%1
Sonda se nedotkla podle očekávání. Přerušte úlohu, nebo pokračujte.</translation>
    </message>
    <message>
        <source>Tool lifted %1</source>
        <translation>Nástroj zvednut %1</translation>
    </message>
    <message>
        <source>Stop the spindle</source>
        <translation>Zastavit vřeteno</translation>
    </message>
    <message>
        <source>New feed (0 = unchanged):</source>
        <translation>Nový posuv (0 = beze změny):</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Pokračovat</translation>
    </message>
    <message>
        <source>Lift tool</source>
        <translation>Zvednout nástroj</translation>
    </message>
    <message>
        <source>Lower and continue</source>
        <translation>Spustit a pokračovat</translation>
    </message>
    <message>
        <source>Lower, stay paused</source>
        <translation>Spustit, zůstat pozastaveno</translation>
    </message>
    <message>
        <source>Abort job</source>
        <translation>Přerušit úlohu</translation>
    </message>
    <message>
        <source>Off the planned path %1</source>
        <translation>Mimo plánovanou dráhu %1</translation>
    </message>
    <message>
        <source>The machine&apos;s position left the path that was sent: a command was damaged on the serial line in a way its checksum cannot show, and the unit ran it. The machine has stopped. Check the workpiece. Continue lifts the tool, returns to the last point verified on the path and runs the job on from there; or Abort the job.</source>
        <translation>Poloha stroje opustila odeslanou dráhu: příkaz se na sériové lince poškodil tak, že to jeho kontrolní součet nepozná, a jednotka ho provedla. Stroj stojí. Zkontrolujte obrobek. Pokračovat zvedne nástroj, vrátí se do posledního ověřeného bodu dráhy a odtud úlohu dokončí; nebo úlohu přerušte.</translation>
    </message>
    <message>
        <source>The machine has stopped along its ramp and keeps the rest of the job. Continue, or lift the tool to change or clean it (the spindle and coolant go off for a lifted tool).</source>
        <translation>Stroj zabrzdil po rampě a zbytek úlohy si drží. Pokračujte, nebo zvedněte nástroj k výměně či očištění (při zvednutém nástroji se vřeteno a chlazení vypnou).</translation>
    </message>
    <message>
        <source>The spindle and coolant are off for the hold. Continue switches them on again and waits %1 s for the spindle before the tool moves.</source>
        <translation>Vřeteno a chlazení jsou po dobu zastavení vypnuté. Pokračovat je znovu zapne a počká %1 s na vřeteno, než se nástroj pohne.</translation>
    </message>
    <message>
        <source>The spindle is running.</source>
        <translation>Vřeteno běží.</translation>
    </message>
    <message>
        <source>The spindle is off.</source>
        <translation>Vřeteno je vypnuté.</translation>
    </message>
    <message>
        <source>While the job is held: the spindle and coolant off (ticked) or on again (unticked). Ticked, a pause stops them as soon as the machine stands.</source>
        <translation>Během zastavené úlohy: vřeteno a chlazení vypnout (zaškrtnuto) nebo znovu zapnout (nezaškrtnuto). Zaškrtnuto: pauza je vypne, jakmile stroj stojí.</translation>
    </message>
    <message>
        <source>The feed from here on, as the feed override for the rest of the job</source>
        <translation>Posuv od tohoto místa, jako korekce posuvu pro zbytek úlohy</translation>
    </message>
    <message>
        <source>The spindle and coolant are off. Change, measure or clean the tool; you may jog the machine away by steps. Lowering switches the spindle and coolant on again as they were, waits %1 s for the spindle to reach its speed, returns exactly to where the tool was lifted, lowers it into the work and continues. Abort ends the job here with the tool up.</source>
        <translation>Vřeteno a chlazení jsou vypnuté. Vyměňte, změřte nebo očistěte nástroj; stroj můžete krokově odjet. Spuštění nástroje zapne vřeteno a chlazení tak, jak byly, počká %1 s, než vřeteno dosáhne otáček, vrátí se přesně do místa zvednutí, spustí nástroj do materiálu a pokračuje. Přerušení zde úlohu ukončí se zvednutým nástrojem.</translation>
    </message>
    <message>
        <source>A new feed entered below is the feed override for the rest of the job.</source>
        <translation>Nový posuv zadaný níže platí jako korekce posuvu pro zbytek úlohy.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::JogPanel</name>
    <message>
        <source>Home %1</source>
        <translation>Reference %1</translation>
    </message>
    <message>
        <source>Find the home switch of %1</source>
        <translation>Najet do reference osy %1 (referenční spínač)</translation>
    </message>
    <message>
        <source>Home all</source>
        <translation>Reference všech os</translation>
    </message>
    <message>
        <source>Home every axis in the order of the machine profile</source>
        <translation>Najet do reference všemi osami v pořadí podle profilu stroje</translation>
    </message>
    <message>
        <source>Step (mm):</source>
        <translation>Krok (mm):</translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation>Plynule</translation>
    </message>
    <message>
        <source>Move while the button or key is held</source>
        <translation>Pohyb, dokud je tlačítko nebo klávesa stisknuta</translation>
    </message>
    <message>
        <source>Jog feed:</source>
        <translation>Posuv ručního pohybu:</translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation>Ruční kolečko (MPG)</translation>
    </message>
    <message>
        <source>Keyboard: arrows jog X/Y, Page Up/Page Down jog Z</source>
        <translation>Klávesnice: šipky posouvají X/Y, Page Up/Page Down posouvá Z</translation>
    </message>
    <message>
        <source>%1 not homed: soft limits off, slow jog</source>
        <translation>%1 bez reference: softwarové limity vypnuty, pomalý ruční posuv</translation>
    </message>
    <message>
        <source>Before homing the counters do not say where the axes are: jogging ignores the soft limits and runs at most at the homing speed. Home the machine to have the limits and the full jog speed; a program asks for homing before it runs.</source>
        <translation>Před najetím do reference čítače neříkají, kde osy jsou: ruční posuv nebere ohled na softwarové limity a jede nejvýše rychlostí hledání reference. Najeďte stroj do reference, aby platily limity a plná rychlost posuvu; program si před spuštěním o referenci řekne.</translation>
    </message>
    <message>
        <source>Step (in):</source>
        <translation>Krok (in):</translation>
    </message>
</context>
<context>
    <name>frezka::gui::LoadProgress</name>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Stop loading this program (the program loaded before stays)</source>
        <translation>Zastavit načítání tohoto programu (dříve načtený program zůstane)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::MainWindow</name>
    <message>
        <source>About Frezka</source>
        <translation>O aplikaci Frezka</translation>
    </message>
    <message>
        <source>&lt;b&gt;Frezka %1&lt;/b&gt;&lt;br&gt;Runs CNC mills through GVE interpolators.</source>
        <translation>&lt;b&gt;Frezka %1&lt;/b&gt;&lt;br&gt;Řídí CNC frézky přes interpolátory GVE.</translation>
    </message>
    <message>
        <source>Frezka</source>
        <translation>Frezka</translation>
    </message>
    <message>
        <source>Frezka — %1</source>
        <translation>Frezka — %1</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Poloha</translation>
    </message>
    <message>
        <source>Program run</source>
        <translation>Běh programu</translation>
    </message>
    <message>
        <source>Jog and homing</source>
        <translation>Ruční pohyb a reference</translation>
    </message>
    <message>
        <source>Spindle and outputs</source>
        <translation>Vřeteno a výstupy</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Konzole</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Rychlost</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <source>&amp;Open program…</source>
        <translation>&amp;Otevřít program…</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Otevřít &amp;nedávné</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Konec</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Stroj</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Připojit</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Odpojit</translation>
    </message>
    <message>
        <source>&amp;Settings…</source>
        <translation>&amp;Nastavení…</translation>
    </message>
    <message>
        <source>&amp;Unit configuration (EEPROM)…</source>
        <translation>&amp;Konfigurace jednotky (EEPROM)…</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Zobrazení</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Výchozí rozvržení</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Nástroje</translation>
    </message>
    <message>
        <source>&amp;Grinder transfer (ANC/K51)…</source>
        <translation>Přenos pro &amp;brusky (ANC/K51)…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Nápo&amp;věda</translation>
    </message>
    <message>
        <source>&amp;About Frezka</source>
        <translation>&amp;O aplikaci Frezka</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Žádný program</translation>
    </message>
    <message>
        <source>Open program</source>
        <translation>Otevřít program</translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.gcode *.tap *.txt);;All files (*)</source>
        <translation>G-kód (*.nc *.ngc *.gcode *.tap *.txt);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>Načítám %1…</translation>
    </message>
    <message numerus="yes">
        <source>%1 — %n line(s)</source>
        <translation>
            <numerusform>%1 — %n řádek</numerusform>
            <numerusform>%1 — %n řádky</numerusform>
            <numerusform>%1 — %n řádků</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The program has %n error(s); nothing will run until they are fixed.
%1</source>
        <translation>
            <numerusform>Program má %n chybu; nic se nespustí, dokud nebude opravena.
%1</numerusform>
            <numerusform>Program má %n chyby; nic se nespustí, dokud nebudou opraveny.
%1</numerusform>
            <numerusform>Program má %n chyb; nic se nespustí, dokud nebudou opraveny.
%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Laser</source>
        <translation>Laser</translation>
    </message>
    <message>
        <source>Cover lock</source>
        <translation>Zámek krytu</translation>
    </message>
    <message>
        <source>Tool release</source>
        <translation>Uvolnění nástroje</translation>
    </message>
    <message>
        <source>Tool cover</source>
        <translation>Kryt nástrojů</translation>
    </message>
    <message>
        <source>Program finished in %1.</source>
        <translation>Program dokončen za %1.</translation>
    </message>
    <message>
        <source>Program finished.</source>
        <translation>Program dokončen.</translation>
    </message>
    <message>
        <source>No output of this machine is set up for that function; assign one in Settings › Machine profile › Outputs.</source>
        <translation>Žádný výstup tohoto stroje nemá tuto funkci; přiřaďte ji v Nastavení › Profil stroje › Výstupy.</translation>
    </message>
    <message numerus="yes">
        <source>Check passed: %n move(s), estimated time %1, within the soft limits.</source>
        <translation>
            <numerusform>Kontrola v pořádku: %n pohyb, odhadovaný čas %1, v softwarových limitech.</numerusform>
            <numerusform>Kontrola v pořádku: %n pohyby, odhadovaný čas %1, v softwarových limitech.</numerusform>
            <numerusform>Kontrola v pořádku: %n pohybů, odhadovaný čas %1, v softwarových limitech.</numerusform>
        </translation>
    </message>
    <message>
        <source>Check passed.</source>
        <translation>Kontrola v pořádku.</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Řádek %1</translation>
    </message>
    <message>
        <source>The link to the unit was lost. The job position is kept: reconnect, then Resume.</source>
        <translation>Spojení s jednotkou bylo ztraceno. Poloha v úloze je uchována: připojte se znovu a pak stiskněte Pokračovat.</translation>
    </message>
    <message>
        <source>Unit EEPROM differs from the profile: %1 is %2 in the unit, %3 in the profile</source>
        <translation>EEPROM jednotky se liší od profilu: %1 je v jednotce %2, v profilu %3</translation>
    </message>
    <message>
        <source>The unit reported a problem: %1</source>
        <translation>Jednotka hlásí problém: %1</translation>
    </message>
    <message>
        <source>Command: %1</source>
        <translation>Příkaz: %1</translation>
    </message>
    <message>
        <source>Reply: %1</source>
        <translation>Odpověď: %1</translation>
    </message>
    <message>
        <source>Program line: %1</source>
        <translation>Řádek programu: %1</translation>
    </message>
    <message>
        <source>Open a program first.</source>
        <translation>Nejprve otevřete program.</translation>
    </message>
    <message>
        <source>Jog refused: %1 would go to %2 mm, outside the soft limits %3 … %4 mm.</source>
        <translation>Ruční pohyb odmítnut: %1 by jela na %2 mm, mimo softwarové limity %3 … %4 mm.</translation>
    </message>
    <message>
        <source>Set the work zero while the machine is ready and still.</source>
        <translation>Nulový bod obrobku nastavujte, když je stroj připraven a stojí.</translation>
    </message>
    <message>
        <source>The new port is used when you connect again after the job.</source>
        <translation>Nový port se použije, až se po úloze znovu připojíte.</translation>
    </message>
    <message>
        <source>Manual line done.</source>
        <translation>Ruční řádek dokončen.</translation>
    </message>
    <message>
        <source>Using the port used last, %1 (the machine profile says %2).</source>
        <translation>Používá se naposledy použitý port %1 (profil stroje uvádí %2).</translation>
    </message>
    <message>
        <source>built-in emulator</source>
        <translation>vestavěný emulátor</translation>
    </message>
    <message>
        <source>%1, %2 Bd</source>
        <translation>%1, %2 Bd</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Program comment: %1</source>
        <translation>Komentář programu: %1</translation>
    </message>
    <message>
        <source>State: %1 → %2</source>
        <translation>Stav: %1 → %2</translation>
    </message>
    <message>
        <source>The machine is not homed: its soft limits refer to nothing yet. Home all axes now and then run the program?</source>
        <translation>Stroj není v referenci: jeho softwarové limity zatím k ničemu neodkazují. Najet teď všemi osami do reference a pak spustit program?</translation>
    </message>
    <message>
        <source>Home and run</source>
        <translation>Reference a spustit</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Stav</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Chlazení</translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation>Ofuk</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Klávesové zkratky</translation>
    </message>
    <message>
        <source>Run from &amp;line…</source>
        <translation>Spustit od &amp;řádku…</translation>
    </message>
    <message>
        <source>Run the &amp;whole program</source>
        <translation>Spustit &amp;celý program</translation>
    </message>
    <message>
        <source>Open a program first, then choose the line to run from.</source>
        <translation>Nejprve otevřete program, pak zvolte řádek, od kterého jej spustit.</translation>
    </message>
    <message>
        <source>Line %1 is not in the program (lines 1 to %2): choose one of its lines.</source>
        <translation>Řádek %1 v programu není (má řádky 1 až %2): zvolte některý z nich.</translation>
    </message>
    <message>
        <source>The machine is busy (%1): run from a line once it is ready.</source>
        <translation>Stroj je zaneprázdněn (%1): spusťte od řádku, až bude připraven.</translation>
    </message>
    <message>
        <source>Run from line</source>
        <translation>Spustit od řádku</translation>
    </message>
    <message>
        <source>Start the program at line (1 to %1):</source>
        <translation>Spustit program od řádku (1 až %1):</translation>
    </message>
    <message>
        <source>Run from line %1 is ready: the view shows the approach. Run starts it; Machine › Run the whole program goes back.</source>
        <translation>Spuštění od řádku %1 je připraveno: náhled ukazuje najetí. Spustit je zahájí; Stroj › Spustit celý program vrátí celý program.</translation>
    </message>
    <message>
        <source>Re&amp;load program</source>
        <translation>&amp;Znovu načíst program</translation>
    </message>
    <message>
        <source>The program cannot be reloaded while its job runs: let it finish or abort it, then reload.</source>
        <translation>Program nelze znovu načíst, dokud běží jeho úloha: nechte ji doběhnout nebo ji přerušte a pak program načtěte znovu.</translation>
    </message>
    <message>
        <source>%1 has changed on disk. Reload it? Until then the listing, the preview and the job are of the version read before.</source>
        <translation>Soubor %1 se na disku změnil. Načíst jej znovu? Do té doby výpis, náhled i úloha odpovídají dříve načtené verzi.</translation>
    </message>
    <message>
        <source>Reload</source>
        <translation>Načíst znovu</translation>
    </message>
    <message>
        <source>Keep the version read before</source>
        <translation>Ponechat dříve načtenou verzi</translation>
    </message>
    <message>
        <source>Work offset %1 set to X %2, Y %3, Z %4 mm.</source>
        <translation>Posunutí nulového bodu %1 nastaveno na X %2, Y %3, Z %4 mm.</translation>
    </message>
    <message>
        <source>Program &amp;info…</source>
        <translation>&amp;Informace o programu…</translation>
    </message>
    <message>
        <source>G20: the program is in inches</source>
        <translation>G20: program je v palcích</translation>
    </message>
    <message>
        <source>G21: the program is in mm</source>
        <translation>G21: program je v mm</translation>
    </message>
    <message>
        <source>&amp;Tool table…</source>
        <translation>&amp;Tabulka nástrojů…</translation>
    </message>
    <message>
        <source>The machine profile names no tool table file: set it in Machine › Settings (Tools), e.g. tool.tbl.</source>
        <translation>Profil stroje neuvádí soubor tabulky nástrojů: nastavte ho ve Stroj › Nastavení (Nástroje), např. tool.tbl.</translation>
    </message>
    <message>
        <source>Tool table saved; programs are checked with it.</source>
        <translation>Tabulka nástrojů uložena; programy se kontrolují s ní.</translation>
    </message>
    <message>
        <source>no comment in the tool table</source>
        <translation>bez komentáře v tabulce nástrojů</translation>
    </message>
    <message>
        <source>Tool %1: %2 (length %3 mm, diameter %4 mm)</source>
        <translation>Nástroj %1: %2 (délka %3 mm, průměr %4 mm)</translation>
    </message>
    <message>
        <source>The program changed the tool table (G10 L1, L10 or L11): %1 saved.</source>
        <translation>Program změnil tabulku nástrojů (G10 L1, L10 nebo L11): %1 uložena.</translation>
    </message>
    <message>
        <source>Loading %1 was cancelled; no program is loaded.</source>
        <translation>Načítání %1 bylo zrušeno; není načten žádný program.</translation>
    </message>
    <message>
        <source>Loading %1 was cancelled; %2 stays loaded.</source>
        <translation>Načítání %1 bylo zrušeno; zůstává načten %2.</translation>
    </message>
    <message>
        <source>Save serial &amp;trace…</source>
        <translation>Uložit sériový &amp;záznam…</translation>
    </message>
    <message>
        <source>Save serial trace</source>
        <translation>Uložit sériový záznam</translation>
    </message>
    <message>
        <source>Serial traces (*.trace *.txt)</source>
        <translation>Sériové záznamy (*.trace *.txt)</translation>
    </message>
    <message>
        <source>Serial trace saved to %1</source>
        <translation>Sériový záznam uložen do %1</translation>
    </message>
    <message>
        <source>The serial trace is off. Set how much of it to keep in Settings › Application, then repeat what went wrong and save it again.</source>
        <translation>Sériový záznam je vypnutý. V Nastavení › Aplikace nastavte, kolik ho uchovávat, pak zopakujte, co se pokazilo, a uložte ho znovu.</translation>
    </message>
    <message>
        <source>C&amp;ommission this machine…</source>
        <translation>&amp;Uvést tento stroj do provozu…</translation>
    </message>
    <message>
        <source>&amp;Height map…</source>
        <translation>&amp;Výšková mapa…</translation>
    </message>
    <message>
        <source>Height map applied: the program is bent to it (heights %1 to %2 mm).</source>
        <translation>Výšková mapa použita: program je přizpůsoben povrchu (výšky %1 až %2 mm).</translation>
    </message>
    <message>
        <source>Height map removed: the program runs as written.</source>
        <translation>Výšková mapa odebrána: program poběží tak, jak je napsán.</translation>
    </message>
    <message>
        <source>Tool %1 measured on the tool sensor: %2 mm long.</source>
        <translation>Nástroj %1 změřen na snímači nástrojů: délka %2 mm.</translation>
    </message>
    <message>
        <source>Unit %1: %2</source>
        <translation>Jednotka %1: %2</translation>
    </message>
    <message>
        <source>Another unit becomes this window&apos;s machine only while every unit on the line is idle; wait, or stop the units, then choose again.</source>
        <translation>Jiná jednotka se může stát strojem tohoto okna, jen když všechny jednotky na lince stojí; počkejte nebo jednotky zastavte a zvolte znovu.</translation>
    </message>
    <message>
        <source>This window&apos;s machine is now %1 (address %2).</source>
        <translation>Strojem tohoto okna je nyní %1 (adresa %2).</translation>
    </message>
    <message>
        <source>The units on the machine&apos;s line cannot be set up; fix line.units in the machine profile:
%1</source>
        <translation>Jednotky na lince stroje nelze nastavit; opravte line.units v profilu stroje:
%1</translation>
    </message>
    <message>
        <source>&amp;Probe work zero…</source>
        <translation>&amp;Sondovat nulu obrobku…</translation>
    </message>
    <message>
        <source>&amp;Height map</source>
        <translation>&amp;Výšková mapa</translation>
    </message>
    <message>
        <source>Show the probed or loaded height map in the toolpath view</source>
        <translation>Zobrazit nasondovanou nebo načtenou výškovou mapu v pohledu na dráhu nástroje</translation>
    </message>
    <message>
        <source>Height map &amp;Z scale</source>
        <translation>Měřítko &amp;Z výškové mapy</translation>
    </message>
    <message>
        <source>&amp;True scale</source>
        <translation>&amp;Skutečné měřítko</translation>
    </message>
    <message>
        <source>Heights &amp;exaggerated %1×</source>
        <translation>Výšky &amp;zvětšené %1×</translation>
    </message>
    <message>
        <source>After line %1 the path depends on the probe&apos;s result: it is checked and shown as if the probe ended at its programmed end (provisional), and each part is planned once the probe before it has run.</source>
        <translation>Za řádkem %1 závisí dráha na výsledku sondy: kontroluje se a zobrazuje, jako by sonda skončila v naprogramovaném konci (předběžně), a každá část se naplánuje, až proběhne sonda před ní.</translation>
    </message>
    <message>
        <source>Line %1: the probe&apos;s result was followed; the rest of the program is shown and runs as interpreted with it.</source>
        <translation>Řádek %1: výsledek sondy byl převzat; zbytek programu se zobrazuje a běží tak, jak byl s ním znovu interpretován.</translation>
    </message>
    <message>
        <source>%1 X%2 Y%3 Z%4 A%5</source>
        <translation>%1 X%2 Y%3 Z%4 A%5</translation>
    </message>
    <message>
        <source>The program set work offsets (G10 L2/L20), kept: %1 (machine mm).</source>
        <translation>Program nastavil pracovní posunutí (G10 L2/L20), ponechána: %1 (strojní mm).</translation>
    </message>
    <message>
        <source>The port %1 is not opened: on the virtual clock (--clock virtual) only the built-in emulator runs. Choose the emulator as the port, or start Frezka without --clock virtual.</source>
        <translation>Port %1 se neotevírá: na virtuálních hodinách (--clock virtual) běží jen vestavěný emulátor. Zvolte jako port emulátor, nebo spusťte Frezku bez --clock virtual.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::OutputsPanel</name>
    <message>
        <source>Spindle</source>
        <translation>Vřeteno</translation>
    </message>
    <message>
        <source>Switch the spindle on or off at the speed on the right</source>
        <translation>Zapnout nebo vypnout vřeteno s otáčkami vpravo</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Otáčky:</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Chlazení</translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation>Ofuk</translation>
    </message>
    <message>
        <source>Feed:</source>
        <translation>Posuv:</translation>
    </message>
    <message>
        <source>Feed override in percent of the programmed feed (XM)</source>
        <translation>Korekce posuvu v procentech programovaného posuvu (XM)</translation>
    </message>
    <message>
        <source>Raise every queued speed by 6.25 % (XU)</source>
        <translation>Zvýšit všechny rychlosti ve frontě o 6,25 % (XU)</translation>
    </message>
    <message>
        <source>Lower every queued speed by 6.25 % (XD)</source>
        <translation>Snížit všechny rychlosti ve frontě o 6,25 % (XD)</translation>
    </message>
    <message>
        <source>%1 % (runs %2 %)</source>
        <translation>%1 % (běží %2 %)</translation>
    </message>
    <message>
        <source>The serial link cannot carry the program&apos;s motion at %1 %: the unit runs %2 % until the motion ahead is slow enough, so that it never runs dry.</source>
        <translation>Sériová linka nestačí přenášet pohyb programu při %1 %: jednotka běží na %2 %, dokud pohyb před ní není dost pomalý, aby se jí fronta nikdy nevyprázdnila.</translation>
    </message>
    <message>
        <source>Spindle:</source>
        <translation>Vřeteno:</translation>
    </message>
    <message>
        <source>Spindle override in percent of the programmed speed: the turning spindle at once, and every spindle speed of the rest of the job</source>
        <translation>Korekce otáček vřetena v procentech naprogramovaných otáček: běžící vřeteno ihned a všechny otáčky ve zbytku úlohy</translation>
    </message>
    <message>
        <source>Spindle speed as programmed</source>
        <translation>Otáčky vřetena podle programu</translation>
    </message>
</context>
<context>
    <name>frezka::gui::PlacementBar</name>
    <message>
        <source>%1 goes to %2 mm at line %3, %4 mm beyond the travel&apos;s %5 mm.</source>
        <translation>%1 jde od řádku %3 až na %2 mm, o %4 mm za mez pojezdu %5 mm.</translation>
    </message>
    <message>
        <source>The program leaves the machine&apos;s travel at the current work zero. %1 Its coordinates are probably relative to the stock: bring the tool to the chosen point of the stock, its tip on the stock&apos;s top (the program&apos;s Z0), and set the work zero there.</source>
        <translation>Program při současném nulovém bodu obrobku opouští pojezd stroje. %1 Jeho souřadnice jsou nejspíš vztažené k polotovaru: najeďte nástrojem na zvolený bod polotovaru, špičkou na jeho horní plochu (Z0 programu), a nastavte tam nulový bod.</translation>
    </message>
    <message>
        <source>With the work zero set here the program would sit at %1 mm: inside the travel.</source>
        <translation>S nulovým bodem nastaveným zde by program ležel v %1 mm: uvnitř pojezdu.</translation>
    </message>
    <message>
        <source>With the work zero set here the program would sit at %1 mm: still outside the travel. Move to the stock first or choose another point.</source>
        <translation>S nulovým bodem nastaveným zde by program ležel v %1 mm: stále mimo pojezd. Nejprve najeďte k polotovaru nebo zvolte jiný bod.</translation>
    </message>
    <message>
        <source>Here is the stock&apos;s:</source>
        <translation>Zde je na polotovaru:</translation>
    </message>
    <message>
        <source>program&apos;s X0 Y0</source>
        <translation>X0 Y0 programu</translation>
    </message>
    <message>
        <source>front left corner</source>
        <translation>přední levý roh</translation>
    </message>
    <message>
        <source>front right corner</source>
        <translation>přední pravý roh</translation>
    </message>
    <message>
        <source>back left corner</source>
        <translation>zadní levý roh</translation>
    </message>
    <message>
        <source>back right corner</source>
        <translation>zadní pravý roh</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>střed</translation>
    </message>
    <message>
        <source>Set the work zero here</source>
        <translation>Nastavit nulový bod zde</translation>
    </message>
    <message>
        <source>Sets the active work offset so that the chosen point of the program is at the current X/Y and the program&apos;s Z0 at the current Z</source>
        <translation>Nastaví aktivní posunutí nulového bodu tak, aby zvolený bod programu byl v současné poloze X/Y a Z0 programu v současné poloze Z</translation>
    </message>
    <message>
        <source>Shift into the travel</source>
        <translation>Posunout do pojezdu</translation>
    </message>
    <message>
        <source>Shifts the active work offset by the least that puts the whole program inside the soft limits (as frezka-cli check suggests)</source>
        <translation>Posune aktivní posunutí nulového bodu o nejmenší hodnotu, která dostane celý program do softwarových mezí (jak navrhuje frezka-cli check)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::Plan</name>
    <message>
        <source>the move leaves the machine&apos;s travel (soft limits); check the work zero and the program</source>
        <translation>pohyb opouští pracovní rozsah stroje (softwarové limity); zkontrolujte nulový bod obrobku a program</translation>
    </message>
    <message>
        <source>the program moves an axis this machine does not have</source>
        <translation>program pohybuje osou, kterou tento stroj nemá</translation>
    </message>
    <message>
        <source>the position is beyond the unit&apos;s step counters</source>
        <translation>poloha je mimo rozsah čítačů kroků jednotky</translation>
    </message>
    <message>
        <source>a feed move has no feed rate (F)</source>
        <translation>pracovní pohyb nemá posuv (F)</translation>
    </message>
    <message>
        <source>the spindle speed (S) is above the machine&apos;s maximum</source>
        <translation>otáčky vřetene (S) jsou nad maximem stroje</translation>
    </message>
    <message>
        <source>the unit cannot do this</source>
        <translation>jednotka toto neumí</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>%1:%2: %3 (%4)</source>
        <translation>%1:%2: %3 (%4)</translation>
    </message>
    <message>
        <source>the feed is above what the machine&apos;s axes can do; it runs slower than programmed</source>
        <translation>posuv je vyšší, než zvládnou osy stroje; poběží pomaleji, než je naprogramováno</translation>
    </message>
</context>
<context>
    <name>frezka::gui::PortSettingsRow</name>
    <message>
        <source>Serial port; a path such as /dev/pts/3 may be typed.</source>
        <translation>Sériový port; lze zapsat i cestu, např. /dev/pts/3.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>even</source>
        <translation>sudá</translation>
    </message>
    <message>
        <source>odd</source>
        <translation>lichá</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>Rychlost (Bd):</translation>
    </message>
    <message>
        <source>Data bits:</source>
        <translation>Datové bity:</translation>
    </message>
    <message>
        <source>Parity:</source>
        <translation>Parita:</translation>
    </message>
    <message>
        <source>Stop bits:</source>
        <translation>Stop bity:</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProbeSetupPicture</name>
    <message>
        <source>work</source>
        <translation>obrobek</translation>
    </message>
    <message>
        <source>plate</source>
        <translation>destička</translation>
    </message>
    <message>
        <source>tool</source>
        <translation>nástroj</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProbeZeroDialog</name>
    <message>
        <source>1. Lay the plate on the work and connect the probe&apos;s clip to the tool.
2. Jog the tool over the plate, a few mm above it.
3. Press Probe: the tool goes down until it touches (fast, then slow) and backs off; the work&apos;s top becomes Z 0.</source>
        <translation>1. Položte destičku na obrobek a připojte svorku sondy k nástroji.
2. Najeďte nástrojem nad destičku, několik mm nad ni.
3. Stiskněte Sondovat: nástroj sjede dolů, dokud se nedotkne (rychle, pak pomalu), a odjede; horní plocha obrobku bude Z 0.</translation>
    </message>
    <message>
        <source>1. Jog the tool beside the edge, below the work&apos;s top, within the travel of it.
2. Choose the direction toward the edge and the tool&apos;s diameter.
3. Press Probe: the tool moves until it touches and comes back; the edge becomes 0 on that axis.</source>
        <translation>1. Najeďte nástrojem vedle hrany, pod horní plochu obrobku, v dosahu dráhy.
2. Zvolte směr k hraně a průměr nástroje.
3. Stiskněte Sondovat: nástroj jede, dokud se nedotkne, a vrátí se; hrana bude na té ose 0.</translation>
    </message>
    <message>
        <source>1. Jog the tool off the corner diagonally, below the work&apos;s top.
2. Set the reach: how far to move beside each face (more than the distance to the corner plus the tool&apos;s radius).
3. Press Probe: X first, then Y; the corner becomes X 0 Y 0.</source>
        <translation>1. Najeďte nástrojem šikmo mimo roh, pod horní plochu obrobku.
2. Nastavte přejezd: jak daleko popojet vedle každé stěny (víc než vzdálenost k rohu plus poloměr nástroje).
3. Stiskněte Sondovat: nejdřív X, pak Y; roh bude X 0 Y 0.</translation>
    </message>
    <message>
        <source>1. Jog the tool into the pocket near its corner, below the top.
2. Choose the directions toward the two walls.
3. Press Probe: X first, then Y, both from where the tool stands; the corner becomes X 0 Y 0.</source>
        <translation>1. Najeďte nástrojem do kapsy blízko jejího rohu, pod horní plochu.
2. Zvolte směry k oběma stěnám.
3. Stiskněte Sondovat: nejdřív X, pak Y, obojí z místa, kde nástroj stojí; roh bude X 0 Y 0.</translation>
    </message>
    <message>
        <source>Probing…</source>
        <translation>Sonduje se…</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Zastavit</translation>
    </message>
    <message>
        <source>&amp;Probe</source>
        <translation>&amp;Sondovat</translation>
    </message>
    <message>
        <source>Nothing was set.</source>
        <translation>Nic nebylo nastaveno.</translation>
    </message>
    <message>
        <source>%1 is now X %2, Y %3, Z %4 (machine mm of its zero).</source>
        <translation>%1 je nyní X %2, Y %3, Z %4 (strojní mm své nuly).</translation>
    </message>
    <message>
        <source>Probing stopped: the tool goes back to where it started. Close the dialog when it is there.</source>
        <translation>Sondování zastaveno: nástroj se vrací tam, kde začal. Dialog zavřete, až tam bude.</translation>
    </message>
    <message>
        <source>Probe work zero</source>
        <translation>Sondovat nulu obrobku</translation>
    </message>
    <message>
        <source>Z from a touch plate</source>
        <translation>Z dotykovou destičkou</translation>
    </message>
    <message>
        <source>X from an edge</source>
        <translation>X z hrany</translation>
    </message>
    <message>
        <source>Y from an edge</source>
        <translation>Y z hrany</translation>
    </message>
    <message>
        <source>X and Y from an outside corner</source>
        <translation>X a Y z vnějšího rohu</translation>
    </message>
    <message>
        <source>X and Y from an inside corner</source>
        <translation>X a Y z vnitřního rohu</translation>
    </message>
    <message>
        <source>What to probe</source>
        <translation>Co sondovat</translation>
    </message>
    <message>
        <source>X direction toward the work</source>
        <translation>Směr X k obrobku</translation>
    </message>
    <message>
        <source>Y direction toward the work</source>
        <translation>Směr Y k obrobku</translation>
    </message>
    <message>
        <source>Plate thickness (mm)</source>
        <translation>Tloušťka destičky (mm)</translation>
    </message>
    <message>
        <source>Tool diameter (mm)</source>
        <translation>Průměr nástroje (mm)</translation>
    </message>
    <message>
        <source>Travel at most (mm)</source>
        <translation>Dráha nejvýše (mm)</translation>
    </message>
    <message>
        <source>Reach beside each face (mm)</source>
        <translation>Přejezd vedle každé stěny (mm)</translation>
    </message>
    <message>
        <source>Probing feed (mm/min)</source>
        <translation>Posuv sondování (mm/min)</translation>
    </message>
    <message>
        <source>Back-off before the slow probe (mm)</source>
        <translation>Odjetí před pomalým sondováním (mm)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Zavřít</translation>
    </message>
</context>
<context>
    <name>frezka::gui::Profile</name>
    <message>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <source>the file cannot be read or written</source>
        <translation>soubor nelze číst ani zapisovat</translation>
    </message>
    <message>
        <source>the file is not valid JSON</source>
        <translation>soubor není platný JSON</translation>
    </message>
    <message>
        <source>the value has the wrong type</source>
        <translation>hodnota má chybný typ</translation>
    </message>
    <message>
        <source>unknown key (a typo?)</source>
        <translation>neznámý klíč (překlep?)</translation>
    </message>
    <message>
        <source>the value is outside its range</source>
        <translation>hodnota je mimo povolený rozsah</translation>
    </message>
    <message>
        <source>the value is none of the allowed ones</source>
        <translation>hodnota není žádná z povolených</translation>
    </message>
    <message>
        <source>the value contradicts another setting or the unit type</source>
        <translation>hodnota odporuje jinému nastavení nebo typu jednotky</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>The machine profile %1 cannot be used; the built-in GVE64 defaults are active until it is fixed:
%2</source>
        <translation>Profil stroje %1 nelze použít; do jeho opravy platí vestavěné výchozí hodnoty GVE64:
%2</translation>
    </message>
    <message>
        <source>Profile name</source>
        <translation>Název profilu</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednotka</translation>
    </message>
    <message>
        <source>Unit type</source>
        <translation>Typ jednotky</translation>
    </message>
    <message>
        <source>Maximum pulse rate</source>
        <translation>Maximální kmitočet kroků</translation>
    </message>
    <message>
        <source>Firmware version</source>
        <translation>Verze firmwaru</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Připojení</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Přenosová rychlost</translation>
    </message>
    <message>
        <source>Checksums</source>
        <translation>Kontrolní součty</translation>
    </message>
    <message>
        <source>Packets</source>
        <translation>Pakety</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation>Osy</translation>
    </message>
    <message>
        <source>X axis</source>
        <translation>Osa X</translation>
    </message>
    <message>
        <source>Y axis</source>
        <translation>Osa Y</translation>
    </message>
    <message>
        <source>Z axis</source>
        <translation>Osa Z</translation>
    </message>
    <message>
        <source>A axis</source>
        <translation>Osa A</translation>
    </message>
    <message>
        <source>Present</source>
        <translation>Osa je osazena</translation>
    </message>
    <message>
        <source>Steps per mm</source>
        <translation>Kroků na mm</translation>
    </message>
    <message>
        <source>Invert direction</source>
        <translation>Obrátit směr</translation>
    </message>
    <message>
        <source>Soft limit min</source>
        <translation>Softwarový limit min</translation>
    </message>
    <message>
        <source>Soft limit max</source>
        <translation>Softwarový limit max</translation>
    </message>
    <message>
        <source>Maximum speed</source>
        <translation>Maximální rychlost</translation>
    </message>
    <message>
        <source>Rapid speed</source>
        <translation>Rychloposuv</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Zrychlení</translation>
    </message>
    <message>
        <source>Maximum speed jump at a corner</source>
        <translation>Maximální skok rychlosti v rohu</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Najíždění do reference</translation>
    </message>
    <message>
        <source>Order (0 = not homed)</source>
        <translation>Pořadí (0 = bez reference)</translation>
    </message>
    <message>
        <source>Direction to the switch (-1/+1)</source>
        <translation>Směr ke spínači (-1/+1)</translation>
    </message>
    <message>
        <source>Maximum search travel</source>
        <translation>Maximální dráha hledání</translation>
    </message>
    <message>
        <source>Speed toward the switch</source>
        <translation>Rychlost ke spínači</translation>
    </message>
    <message>
        <source>Speed off the switch</source>
        <translation>Rychlost od spínače</translation>
    </message>
    <message>
        <source>Maximum back-off travel</source>
        <translation>Maximální dráha odjetí</translation>
    </message>
    <message>
        <source>Position after homing</source>
        <translation>Poloha po najetí do reference</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Pohyb</translation>
    </message>
    <message>
        <source>Corner deviation</source>
        <translation>Odchylka v rohu</translation>
    </message>
    <message>
        <source>Arc chord tolerance</source>
        <translation>Tolerance tětivy oblouku</translation>
    </message>
    <message>
        <source>Pause between stand-alone moves</source>
        <translation>Prodleva mezi samostatnými pohyby</translation>
    </message>
    <message>
        <source>Speed mode</source>
        <translation>Režim rychlosti</translation>
    </message>
    <message>
        <source>Tool lift</source>
        <translation>Zvednutí nástroje</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Vřeteno</translation>
    </message>
    <message>
        <source>Spin-up wait</source>
        <translation>Čekání na roztočení</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Výstupy</translation>
    </message>
    <message>
        <source>OUT1 function</source>
        <translation>Funkce OUT1</translation>
    </message>
    <message>
        <source>OUT2 function</source>
        <translation>Funkce OUT2</translation>
    </message>
    <message>
        <source>OUT3 function</source>
        <translation>Funkce OUT3</translation>
    </message>
    <message>
        <source>Output switched by M7</source>
        <translation>Výstup spínaný M7</translation>
    </message>
    <message>
        <source>Unit EEPROM</source>
        <translation>EEPROM jednotky</translation>
    </message>
    <message>
        <source>Compare with the unit on connect</source>
        <translation>Při připojení porovnat s jednotkou</translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation>Ruční kolečko (MPG)</translation>
    </message>
    <message>
        <source>Handwheel acceleration</source>
        <translation>Zrychlení ručního kolečka</translation>
    </message>
    <message>
        <source>Handwheel maximum speed</source>
        <translation>Maximální rychlost ručního kolečka</translation>
    </message>
    <message>
        <source>Handwheel brake delay</source>
        <translation>Prodleva brzdění ručního kolečka</translation>
    </message>
    <message>
        <source>Handwheel step multiplier</source>
        <translation>Násobitel kroku ručního kolečka</translation>
    </message>
    <message>
        <source>Input that starts homing (0 = off)</source>
        <translation>Vstup spouštějící najetí do reference (0 = vypnuto)</translation>
    </message>
    <message>
        <source>Interrupt enable IN0-7</source>
        <translation>Povolení přerušení IN0-7</translation>
    </message>
    <message>
        <source>Interrupt enable IN14/IN15</source>
        <translation>Povolení přerušení IN14/IN15</translation>
    </message>
    <message>
        <source>Polarity IN0-7</source>
        <translation>Polarita IN0-7</translation>
    </message>
    <message>
        <source>Polarity IN14/IN15</source>
        <translation>Polarita IN14/IN15</translation>
    </message>
    <message>
        <source>A axis slaved to (0 none, 1 X, 2 Y, 3 Z)</source>
        <translation>Osa A sdružena s (0 žádná, 1 X, 2 Y, 3 Z)</translation>
    </message>
    <message>
        <source>PWM for breakout boards</source>
        <translation>PWM pro oddělovací desky</translation>
    </message>
    <message>
        <source>Default spindle speed</source>
        <translation>Výchozí otáčky vřetene</translation>
    </message>
    <message>
        <source>Brake release delay</source>
        <translation>Zpoždění odbrždění brzdy</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automaticky</translation>
    </message>
    <message>
        <source>Path speed (VK)</source>
        <translation>Rychlost po dráze (VK)</translation>
    </message>
    <message>
        <source>Major axis speed (VN)</source>
        <translation>Rychlost hlavní osy (VN)</translation>
    </message>
    <message>
        <source>Unused</source>
        <translation>Nepoužito</translation>
    </message>
    <message>
        <source>Laser</source>
        <translation>Laser</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Chlazení</translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation>Ofuk</translation>
    </message>
    <message>
        <source>Machine cover lock</source>
        <translation>Zámek krytu stroje</translation>
    </message>
    <message>
        <source>Tool release</source>
        <translation>Uvolnění nástroje</translation>
    </message>
    <message>
        <source>Tool cover open</source>
        <translation>Otevření krytu nástrojů</translation>
    </message>
    <message>
        <source>Brake</source>
        <translation>Brzda</translation>
    </message>
    <message>
        <source>Interrupt signal</source>
        <translation>Signalizace přerušení</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Vypnuto</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Zapnuto</translation>
    </message>
    <message>
        <source>On, within the limits</source>
        <translation>Zapnuto, v mezích limit</translation>
    </message>
    <message>
        <source>On, 4th position drives rotary A</source>
        <translation>Zapnuto, 4. poloha ovládá otočnou osu A</translation>
    </message>
    <message>
        <source>On with limits, 4th position drives rotary A</source>
        <translation>Zapnuto s limity, 4. poloha ovládá otočnou osu A</translation>
    </message>
    <message>
        <source>GVE84</source>
        <translation>GVE84</translation>
    </message>
    <message>
        <source>GVE64</source>
        <translation>GVE64</translation>
    </message>
    <message>
        <source>GVE64 PHANTOM</source>
        <translation>GVE64 PHANTOM</translation>
    </message>
    <message>
        <source>GVE114</source>
        <translation>GVE114</translation>
    </message>
    <message>
        <source>Maximum spindle speed</source>
        <translation>Maximální otáčky vřetene</translation>
    </message>
    <message>
        <source>Adapter latency (each way)</source>
        <translation>Latence převodníku (každým směrem)</translation>
    </message>
    <message>
        <source>STEP active edge</source>
        <translation>Aktivní hrana STEP</translation>
    </message>
    <message>
        <source>As the unit left the factory</source>
        <translation>Jak je nastaveno z výroby</translation>
    </message>
    <message>
        <source>Falling edge</source>
        <translation>Sestupná hrana</translation>
    </message>
    <message>
        <source>Rising edge</source>
        <translation>Náběžná hrana</translation>
    </message>
    <message>
        <source>a key of an older profile, read into its successor or ignored</source>
        <translation>klíč staršího profilu, převzatý do nástupce nebo vynechaný</translation>
    </message>
    <message>
        <source>Spindle and coolant off at M0 / M1</source>
        <translation>Vřeteno a chlazení vypnout při M0 / M1</translation>
    </message>
    <message>
        <source>Spindle and coolant off at M6</source>
        <translation>Vřeteno a chlazení vypnout při M6</translation>
    </message>
    <message>
        <source>START button input (0 = none)</source>
        <translation>Vstup tlačítka START (0 = není)</translation>
    </message>
    <message>
        <source>Allow a run before homing (with a warning)</source>
        <translation>Povolit spuštění před najetím do reference (s varováním)</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Nástroje</translation>
    </message>
    <message>
        <source>Tool table file (LinuxCNC .tbl, beside the profile)</source>
        <translation>Soubor tabulky nástrojů (LinuxCNC .tbl, vedle profilu)</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Lines executed at most (a program that never ends)</source>
        <translation>Nejvýše vykonaných řádků (program, který nikdy neskončí)</translation>
    </message>
    <message>
        <source>Moves at most (a program that never ends)</source>
        <translation>Nejvýše pohybů (program, který nikdy neskončí)</translation>
    </message>
    <message>
        <source>Subroutine folders (o&lt;name&gt; call of name.ngc; separated by :)</source>
        <translation>Složky podprogramů (o&lt;název&gt; call souboru název.ngc; oddělené :)</translation>
    </message>
    <message>
        <source>Unit address on the line (0..6)</source>
        <translation>Adresa jednotky na lince (0..6)</translation>
    </message>
    <message>
        <source>Tool length sensor</source>
        <translation>Snímač délky nástroje</translation>
    </message>
    <message>
        <source>X (machine)</source>
        <translation>X (strojní)</translation>
    </message>
    <message>
        <source>Y (machine)</source>
        <translation>Y (strojní)</translation>
    </message>
    <message>
        <source>Clearance Z (machine)</source>
        <translation>Bezpečná výška Z (strojní)</translation>
    </message>
    <message>
        <source>Probing feed</source>
        <translation>Posuv sondování</translation>
    </message>
    <message>
        <source>Slow probing feed</source>
        <translation>Pomalý posuv sondování</translation>
    </message>
    <message>
        <source>Back-off before the slow probe</source>
        <translation>Odjetí před pomalým sondováním</translation>
    </message>
    <message>
        <source>Trip Z of the reference tool (length 0)</source>
        <translation>Z sepnutí referenčního nástroje (délka 0)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProfileEditor</name>
    <message>
        <source>&quot;emulator&quot; = the built-in unit emulator; or a serial port such as /dev/ttyUSB0; or a typed path such as the pty printed by gve-emu</source>
        <translation>„emulator“ = vestavěný emulátor jednotky; nebo sériový port, např. /dev/ttyUSB0; nebo zapsaná cesta, např. pty vypsaný programem gve-emu</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Obecné</translation>
    </message>
    <message>
        <source>The profile is valid.</source>
        <translation>Profil je v pořádku.</translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) — the profile cannot be saved yet.</source>
        <translation>
            <numerusform>%n problém — profil zatím nelze uložit.</numerusform>
            <numerusform>%n problémy — profil zatím nelze uložit.</numerusform>
            <numerusform>%n problémů — profil zatím nelze uložit.</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot load the profile %1:
%2</source>
        <translation>Profil %1 nelze načíst:
%2</translation>
    </message>
    <message>
        <source>The profile has problems; fix them first:
%1</source>
        <translation>Profil obsahuje problémy; nejprve je opravte:
%1</translation>
    </message>
    <message>
        <source>Cannot save the profile %1: %2</source>
        <translation>Profil %1 nelze uložit: %2</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProgramInfoDialog</name>
    <message>
        <source>not planned</source>
        <translation>nenaplánováno</translation>
    </message>
    <message>
        <source>%1: %2 lines, %3 bytes, %4 moves, %5 mm of path, estimated time %6.</source>
        <translation>%1: řádků %2, bajtů %3, pohybů %4, dráha %5 mm, odhadovaný čas %6.</translation>
    </message>
    <message>
        <source>in the spindle</source>
        <translation>ve vřeteni</translation>
    </message>
    <message>
        <source>Program info</source>
        <translation>Informace o programu</translation>
    </message>
    <message>
        <source>Extent (mm)</source>
        <translation>Rozsah (mm)</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Osa</translation>
    </message>
    <message>
        <source>Program min</source>
        <translation>Min. v programu</translation>
    </message>
    <message>
        <source>Program max</source>
        <translation>Max. v programu</translation>
    </message>
    <message>
        <source>Machine min</source>
        <translation>Min. na stroji</translation>
    </message>
    <message>
        <source>Machine max</source>
        <translation>Max. na stroji</translation>
    </message>
    <message>
        <source>Tools in their order</source>
        <translation>Nástroje v pořadí použití</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Nástroj</translation>
    </message>
    <message>
        <source>From line</source>
        <translation>Od řádku</translation>
    </message>
    <message>
        <source>Planned time</source>
        <translation>Plánovaný čas</translation>
    </message>
    <message>
        <source>Cut length (mm)</source>
        <translation>Délka řezu (mm)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProgramListing</name>
    <message>
        <source>Run from this line (%1)…</source>
        <translation>Spustit od tohoto řádku (%1)…</translation>
    </message>
</context>
<context>
    <name>frezka::gui::RunPanel</name>
    <message>
        <source>Elapsed %1</source>
        <translation>Uplynulo %1</translation>
    </message>
    <message>
        <source>Remaining %1</source>
        <translation>Zbývá %1</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Kontrola</translation>
    </message>
    <message>
        <source>Check the program against the machine profile without moving</source>
        <translation>Zkontrolovat program proti profilu stroje bez pohybu</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Spustit</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>Brake along the ramp and hold; Resume continues</source>
        <translation>Zabrzdit po rampě a držet; Pokračovat pokračuje</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovat</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Přerušit</translation>
    </message>
    <message>
        <source>Tool lift…</source>
        <translation>Zvednutí nástroje…</translation>
    </message>
    <message>
        <source>Lift the tool, switch the spindle off, change or clean it, continue</source>
        <translation>Zvednout nástroj, vypnout vřeteno, vyměnit nebo očistit nástroj, pokračovat</translation>
    </message>
    <message>
        <source>Run the checked program (asks for homing first on a machine not homed). The machine&apos;s START button does the same when the profile names its input. Space and Enter never press it.</source>
        <translation>Spustit zkontrolovaný program (u stroje bez reference se nejprve zeptá na najetí do reference). Totéž udělá tlačítko START stroje, pokud profil uvádí jeho vstup. Mezerník ani Enter jej nikdy nestisknou.</translation>
    </message>
    <message>
        <source>Continue the held job (the START button does the same)</source>
        <translation>Pokračovat v pozastavené úloze (totéž udělá tlačítko START)</translation>
    </message>
    <message>
        <source>Stop (Esc)</source>
        <translation>Stop (Esc)</translation>
    </message>
    <message>
        <source>Controlled stop (Esc): brake along the ramp and hold the job; the position stays known and Resume continues it. During homing: end homing, the axes not yet homed stay not homed.</source>
        <translation>Řízené zastavení (Esc): zabrzdit po rampě a pozastavit úlohu; poloha zůstává známá a Pokračovat ji dokončí. Při najíždění do reference: ukončit je, osy dosud bez reference zůstanou bez reference.</translation>
    </message>
    <message>
        <source>Brake and drop every queued move: the job ends and cannot be resumed; the position stays known. Also ends homing.</source>
        <translation>Zabrzdit a zahodit všechny pohyby ve frontě: úloha skončí a nelze v ní pokračovat; poloha zůstává známá. Ukončí i najíždění do reference.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SerialMonitor</name>
    <message>
        <source>Hex view</source>
        <translation>Šestnáctkově</translation>
    </message>
    <message>
        <source>Hex bytes</source>
        <translation>Šestnáctkové bajty</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otevřít</translation>
    </message>
    <message>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <source>to port %1</source>
        <translation>na port %1</translation>
    </message>
    <message>
        <source>Stored message, e.g. AA 05 00 00 FF 51 (K51 ENQ) or Z? as text</source>
        <translation>Uložená zpráva, např. AA 05 00 00 FF 51 (K51 ENQ) nebo Z? jako text</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>Capture to file…</source>
        <translation>Zaznamenat do souboru…</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Odeslat</translation>
    </message>
    <message>
        <source>Message:</source>
        <translation>Zpráva:</translation>
    </message>
    <message>
        <source>Port %1: cannot open %2: %3</source>
        <translation>Port %1: %2 nelze otevřít: %3</translation>
    </message>
    <message>
        <source>Port %1: %2</source>
        <translation>Port %1: %2</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavřít</translation>
    </message>
    <message>
        <source>Port %1: watching %2 at %3 Bd.</source>
        <translation>Port %1: sleduji %2 při %3 Bd.</translation>
    </message>
    <message>
        <source>%1 older bytes left the view; capture to a file to keep everything.</source>
        <translation>%1 starších bajtů už není zobrazeno; pro uchování všeho je zaznamenávejte do souboru.</translation>
    </message>
    <message>
        <source>The message &quot;%1&quot; is not hex bytes (e.g. AA 05 00 00 FF 51).</source>
        <translation>Zpráva „%1“ nejsou šestnáctkové bajty (např. AA 05 00 00 FF 51).</translation>
    </message>
    <message>
        <source>Port %1 is not open.</source>
        <translation>Port %1 není otevřen.</translation>
    </message>
    <message>
        <source>The message is empty.</source>
        <translation>Zpráva je prázdná.</translation>
    </message>
    <message>
        <source>Port %1: the message could not be sent: %2</source>
        <translation>Port %1: zprávu nelze odeslat: %2</translation>
    </message>
    <message>
        <source>Capture to file</source>
        <translation>Záznam do souboru</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Do %1 nelze zapisovat: %2</translation>
    </message>
    <message>
        <source>Captured %1 lines to %2.</source>
        <translation>Zaznamenáno %1 řádků do %2.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SettingsDialog</name>
    <message>
        <source>Export profile</source>
        <translation>Exportovat profil</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Profily strojů (*.json)</translation>
    </message>
    <message>
        <source>Load profile</source>
        <translation>Načíst profil</translation>
    </message>
    <message>
        <source>Defaults of the unit type loaded; Apply or Save to use them.</source>
        <translation>Načteny výchozí hodnoty typu jednotky; použijte je tlačítkem Použít nebo Uložit.</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Uloženo do %1.</translation>
    </message>
    <message>
        <source>Loaded %1; Apply to use it.</source>
        <translation>Načteno %1; použijte tlačítkem Použít.</translation>
    </message>
    <message>
        <source>The profile has problems; fix the fields marked red first.</source>
        <translation>Profil obsahuje problémy; nejprve opravte pole označená červeně.</translation>
    </message>
    <message>
        <source>Applied (not yet saved).</source>
        <translation>Použito (zatím neuloženo).</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Nastavení</translation>
    </message>
    <message>
        <source>Machine profile</source>
        <translation>Profil stroje</translation>
    </message>
    <message>
        <source>Application</source>
        <translation>Aplikace</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Načíst…</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Uložit</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportovat…</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>Výchozí</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Jazyk</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Jazyk systému</translation>
    </message>
    <message>
        <source>Reconnect automatically after a lost link</source>
        <translation>Po ztrátě spojení se automaticky znovu připojit</translation>
    </message>
    <message>
        <source>Shortcuts</source>
        <translation>Klávesové zkratky</translation>
    </message>
    <message>
        <source>Lengths shown in</source>
        <translation>Délky zobrazovat v</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>milimetrech (mm)</translation>
    </message>
    <message>
        <source>inches (in)</source>
        <translation>palcích (in)</translation>
    </message>
    <message>
        <source>The DRO, the jog steps and feed, the status panel and the speed plot. The machine, its profile and the programs&apos; own G20/G21 are not affected.</source>
        <translation>Ukazatel polohy, kroky a rychlost ručního posuvu, stavový panel a graf rychlosti. Stroj, jeho profil ani vlastní G20/G21 programů se tím nemění.</translation>
    </message>
    <message>
        <source>Serial trace kept in memory</source>
        <translation>Sériový záznam uchovávaný v paměti</translation>
    </message>
    <message>
        <source> MB</source>
        <translation> MB</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
    <message>
        <source>The last part of the serial line, both ways, saved with Machine › Save serial trace and by itself on an alarm into %1</source>
        <translation>Poslední část provozu na sériové lince oběma směry; ukládá se příkazem Stroj › Uložit sériový záznam a sama při poplachu do %1</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ShortcutEditor</name>
    <message>
        <source>“%1” now has the key %2.</source>
        <translation>„%1“ má nyní klávesu %2.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(žádná)</translation>
    </message>
    <message>
        <source>Every key is back to its default.</source>
        <translation>Všechny klávesy mají opět výchozí hodnoty.</translation>
    </message>
    <message>
        <source>Click a key field and press the new key; it applies at once. A key that another action already has is refused.</source>
        <translation>Klepněte do pole klávesy a stiskněte novou klávesu; platí okamžitě. Klávesa, kterou už má jiná akce, se odmítne.</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Akce</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Klávesa</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Výchozí</translation>
    </message>
    <message>
        <source>Reset to defaults</source>
        <translation>Obnovit výchozí</translation>
    </message>
</context>
<context>
    <name>frezka::gui::Shortcuts</name>
    <message>
        <source>Run the program</source>
        <translation>Spustit program</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovat</translation>
    </message>
    <message>
        <source>Stop: brake along the ramp and hold the job (resumable)</source>
        <translation>Zastavit: zabrzdit po rampě a podržet úlohu (lze pokračovat)</translation>
    </message>
    <message>
        <source>Abort: brake and drop the job</source>
        <translation>Přerušit: zabrzdit a zahodit úlohu</translation>
    </message>
    <message>
        <source>Tool lift</source>
        <translation>Zvednout nástroj</translation>
    </message>
    <message>
        <source>Feed override up (6.25 %)</source>
        <translation>Korekce posuvu nahoru (6,25 %)</translation>
    </message>
    <message>
        <source>Feed override down (6.25 %)</source>
        <translation>Korekce posuvu dolů (6,25 %)</translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation>Korekce posuvu 100 %</translation>
    </message>
    <message>
        <source>Home all axes</source>
        <translation>Najet všechny osy do reference</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Klávesové zkratky</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Akce</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Klávesa</translation>
    </message>
    <message>
        <source>LinuxCNC AXIS</source>
        <translation>LinuxCNC AXIS</translation>
    </message>
    <message>
        <source>Jog X−</source>
        <translation>Posuv X−</translation>
    </message>
    <message>
        <source>Jog X+</source>
        <translation>Posuv X+</translation>
    </message>
    <message>
        <source>Jog Y−</source>
        <translation>Posuv Y−</translation>
    </message>
    <message>
        <source>Jog Y+</source>
        <translation>Posuv Y+</translation>
    </message>
    <message>
        <source>Jog Z−</source>
        <translation>Posuv Z−</translation>
    </message>
    <message>
        <source>Jog Z+</source>
        <translation>Posuv Z+</translation>
    </message>
    <message>
        <source>Work zero of X here</source>
        <translation>Nulový bod X zde</translation>
    </message>
    <message>
        <source>Work zero of Y here</source>
        <translation>Nulový bod Y zde</translation>
    </message>
    <message>
        <source>Work zero of Z here</source>
        <translation>Nulový bod Z zde</translation>
    </message>
    <message>
        <source>Work zero of all axes here</source>
        <translation>Nulový bod všech os zde</translation>
    </message>
    <message>
        <source>Spindle on / off</source>
        <translation>Vřeteno zapnout / vypnout</translation>
    </message>
    <message>
        <source>Give one key (with Ctrl, Shift or Alt if you like), not a sequence of keys.</source>
        <translation>Zadejte jednu klávesu (případně s Ctrl, Shift nebo Alt), ne posloupnost kláves.</translation>
    </message>
    <message>
        <source>%1 is already the key of “%2”. Give that action another key first, or choose a different key.</source>
        <translation>%1 už je klávesou akce „%2“. Nejprve dejte té akci jinou klávesu, nebo zvolte jinou klávesu.</translation>
    </message>
    <message>
        <source>Keys of the main window; change them in Settings › Shortcuts. The jog keys act while held, only when jogging is possible (not while a job runs) and not while a text field has the focus. A text field with the focus keeps the letters typed into it; no key presses a button that merely has the focus.</source>
        <translation>Klávesy hlavního okna; změníte je v Nastavení › Klávesové zkratky. Klávesy ručního posuvu působí, dokud jsou drženy, jen když je ruční posuv možný (ne během úlohy) a ne když má fokus textové pole. Textové pole s fokusem si písmena napsaná do něj ponechá; žádná klávesa nestiskne tlačítko jen proto, že má fokus.</translation>
    </message>
    <message>
        <source>File › Open program</source>
        <translation>Soubor › Otevřít program</translation>
    </message>
    <message>
        <source>File › Reload program</source>
        <translation>Soubor › Znovu načíst program</translation>
    </message>
    <message>
        <source>File › Quit</source>
        <translation>Soubor › Konec</translation>
    </message>
    <message>
        <source>%1 is the key of the menu command “%2”. Choose a different key.</source>
        <translation>%1 je klávesa příkazu nabídky „%2“. Zvolte jinou klávesu.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SimulatedWheel</name>
    <message>
        <source>Simulated wheel:</source>
        <translation>Simulované kolečko:</translation>
    </message>
    <message>
        <source>Simulates the unit&apos;s MPG handwheel on the built-in emulator: choose the axis and the step switch (x1 = 0.01 mm per detent), then turn with − / + (hold to keep turning). It moves the axis only while Handwheel (MPG) is on.</source>
        <translation>Simuluje ruční kolečko MPG jednotky na vestavěném emulátoru: zvolte osu a přepínač kroku (x1 = 0,01 mm na zaklapnutí), pak otáčejte tlačítky − / + (podržením otáčíte dál). Osou pohne jen při zapnutém Ručním kolečku (MPG).</translation>
    </message>
    <message>
        <source>The wheel&apos;s axis switch (4 = the fourth axis or the spindle, as the unit&apos;s EEPROM sets it)</source>
        <translation>Přepínač osy kolečka (4 = čtvrtá osa nebo vřeteno podle nastavení EEPROM jednotky)</translation>
    </message>
    <message>
        <source>The wheel&apos;s step switch: x1 = 0.01 mm, x10 = 0.1 mm, x100 = 1 mm per detent</source>
        <translation>Přepínač kroku kolečka: x1 = 0,01 mm, x10 = 0,1 mm, x100 = 1 mm na zaklapnutí</translation>
    </message>
    <message>
        <source>Turn the simulated wheel one detent back</source>
        <translation>Otočit simulovaným kolečkem o jedno zaklapnutí zpět</translation>
    </message>
    <message>
        <source>Turn the simulated wheel one detent forward</source>
        <translation>Otočit simulovaným kolečkem o jedno zaklapnutí vpřed</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SpeedPlot</name>
    <message>
        <source>%1 along the path (%2 %3)</source>
        <translation>%1 podél dráhy (%2 %3)</translation>
    </message>
    <message>
        <source>%1 %2 at %3 %4, line %5</source>
        <translation>%1 %2 na %3 %4, řádek %5</translation>
    </message>
</context>
<context>
    <name>frezka::gui::StatusPanel</name>
    <message>
        <source>%1 % (runs %2 %)</source>
        <translation>%1 % (běží %2 %)</translation>
    </message>
    <message>
        <source>override %1</source>
        <translation>korekce %1</translation>
    </message>
    <message>
        <source>clockwise (M3)</source>
        <translation>vpravo (M3)</translation>
    </message>
    <message>
        <source>counter-clockwise (M4)</source>
        <translation>vlevo (M4)</translation>
    </message>
    <message>
        <source>on · %1 rpm</source>
        <translation>zapnuto · %1 ot/min</translation>
    </message>
    <message>
        <source>on · %1 · %2 rpm</source>
        <translation>zapnuto · %1 · %2 ot/min</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
    <message>
        <source>none (T0)</source>
        <translation>žádný (T0)</translation>
    </message>
    <message>
        <source>%1 on</source>
        <translation>%1 zap.</translation>
    </message>
    <message>
        <source>%1 off</source>
        <translation>%1 vyp.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádná</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Posuv</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Vřeteno</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Nástroj</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Výstupy</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Režimy</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>V referenci</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Spojení</translation>
    </message>
    <message>
        <source>%1 (override %2 %)</source>
        <translation>%1 (korekce %2 %)</translation>
    </message>
    <message>
        <source>programmed %1 %2 × %3</source>
        <translation>programováno %1 %2 × %3</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ToolTableDialog</name>
    <message>
        <source>Row %1: the tool number must be a whole number from 1 up.</source>
        <translation>Řádek %1: číslo nástroje musí být celé číslo od 1 výše.</translation>
    </message>
    <message>
        <source>Row %1: tool %2 is listed twice; give it another number or remove the row.</source>
        <translation>Řádek %1: nástroj %2 je uveden dvakrát; dejte mu jiné číslo nebo řádek odstraňte.</translation>
    </message>
    <message>
        <source>Row %1: the pocket must be a whole number from 0 up.</source>
        <translation>Řádek %1: pozice musí být celé číslo od 0 výše.</translation>
    </message>
    <message>
        <source>Row %1: the length must be a number of mm, e.g. 42.5.</source>
        <translation>Řádek %1: délka musí být číslo v mm, např. 42.5.</translation>
    </message>
    <message>
        <source>Row %1: the diameter must be a number of mm, 0 or more.</source>
        <translation>Řádek %1: průměr musí být číslo v mm, 0 nebo více.</translation>
    </message>
    <message>
        <source>Tool table</source>
        <translation>Tabulka nástrojů</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Nástroj</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Pozice</translation>
    </message>
    <message>
        <source>Length (mm)</source>
        <translation>Délka (mm)</translation>
    </message>
    <message>
        <source>Diameter (mm)</source>
        <translation>Průměr (mm)</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Komentář</translation>
    </message>
    <message>
        <source>File: %1</source>
        <translation>Soubor: %1</translation>
    </message>
    <message>
        <source>&amp;Add tool</source>
        <translation>&amp;Přidat nástroj</translation>
    </message>
    <message>
        <source>&amp;Remove tool</source>
        <translation>&amp;Odebrat nástroj</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Uložit</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Zavřít</translation>
    </message>
    <message>
        <source>Select the row of the tool in the spindle, then measure it.</source>
        <translation>Vyberte řádek nástroje, který je ve vřetenu, a pak jej změřte.</translation>
    </message>
    <message>
        <source>Measuring tool %1 on the tool sensor…</source>
        <translation>Měří se nástroj %1 na snímači nástrojů…</translation>
    </message>
    <message>
        <source>Tool %1 is %2 mm long (the sensor tripped at machine Z %3).</source>
        <translation>Nástroj %1 je dlouhý %2 mm (snímač sepnul ve strojní Z %3).</translation>
    </message>
    <message>
        <source>S&amp;top measuring</source>
        <translation>&amp;Zastavit měření</translation>
    </message>
    <message>
        <source>&amp;Measure length</source>
        <translation>&amp;Změřit délku</translation>
    </message>
    <message>
        <source>Probes the selected tool on the tool length sensor (fast, then slow) and writes its length into the table.</source>
        <translation>Změří vybraný nástroj na snímači délky nástroje (rychle, pak pomalu) a zapíše jeho délku do tabulky.</translation>
    </message>
    <message>
        <source>Measuring stopped: the tool goes back up to the sensor&apos;s clearance. Close the table when it is up.</source>
        <translation>Měření zastaveno: nástroj vyjíždí zpět do bezpečné výšky snímače. Tabulku zavřete, až bude nahoře.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ToolpathView</name>
    <message>
        <source>Top</source>
        <translation>Shora</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Zepředu</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Zboku</translation>
    </message>
    <message>
        <source>Iso</source>
        <translation>Izometrie</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Celý</translation>
    </message>
    <message>
        <source>Show the whole program</source>
        <translation>Zobrazit celý program</translation>
    </message>
    <message>
        <source>Left drag: orbit · right/middle drag or Shift+left: pan · wheel: zoom</source>
        <translation>Levé tlačítko: otáčení · pravé/prostřední nebo Shift+levé: posun · kolečko: přiblížení</translation>
    </message>
</context>
<context>
    <name>frezka::gui::TransferPanel</name>
    <message>
        <source>Controller → PC</source>
        <translation>Řídicí systém → PC</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Uložit…</translation>
    </message>
    <message>
        <source>Choose file…</source>
        <translation>Vybrat soubor…</translation>
    </message>
    <message>
        <source>PC → Controller</source>
        <translation>PC → řídicí systém</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Ask the controller for its programs (DEJ) and receive them.</source>
        <translation>Vyžádat si programy z řídicího systému (DEJ) a přijmout je.</translation>
    </message>
    <message>
        <source>Send the chosen file to the controller unchanged.</source>
        <translation>Odeslat vybraný soubor beze změny do řídicího systému.</translation>
    </message>
    <message>
        <source>16 characters shown on the controller</source>
        <translation>16 znaků zobrazených na řídicím systému</translation>
    </message>
    <message>
        <source>No file chosen</source>
        <translation>Není vybrán soubor</translation>
    </message>
    <message>
        <source>Header:</source>
        <translation>Hlavička:</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>Délka:</translation>
    </message>
    <message>
        <source>Inner blocks:</source>
        <translation>Vnitřní bloky:</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Soubor:</translation>
    </message>
    <message>
        <source>Messages:</source>
        <translation>Zprávy:</translation>
    </message>
    <message>
        <source>Receiving from the controller…</source>
        <translation>Přijímám z řídicího systému…</translation>
    </message>
    <message>
        <source>Sending %1 to the controller…</source>
        <translation>Odesílám %1 do řídicího systému…</translation>
    </message>
    <message>
        <source>%1 of %2 bytes, %3 left</source>
        <translation>%1 z %2 bajtů, zbývá %3</translation>
    </message>
    <message>
        <source>%1 bytes in %2</source>
        <translation>%1 bajtů za %2</translation>
    </message>
    <message>
        <source>%1 bytes (0x%2)</source>
        <translation>%1 bajtů (0x%2)</translation>
    </message>
    <message>
        <source>Received. Press Save to store the data in a file.</source>
        <translation>Přijato. Tlačítkem Uložit data uložíte do souboru.</translation>
    </message>
    <message>
        <source>Sent; the controller confirmed the transfer.</source>
        <translation>Odesláno, řídicí systém přenos potvrdil.</translation>
    </message>
    <message>
        <source>On the controller, TCHIN programs show &quot;no prg set&quot; once after a transfer: set up the X axis first — select the TCHIN program in AUT and hold RES.</source>
        <translation>Programy TCHIN ukážou na řídicím systému po přenosu jednou „no prg set“: nejprve seřiďte osu X — zvolte program TCHIN v AUT a podržte RES.</translation>
    </message>
    <message>
        <source>Save the controller&apos;s data</source>
        <translation>Uložit data z řídicího systému</translation>
    </message>
    <message>
        <source>Choose the file to send</source>
        <translation>Vyberte soubor k odeslání</translation>
    </message>
    <message>
        <source>Cannot write %1: %2. The received data are kept; choose another file.</source>
        <translation>Do %1 nelze zapisovat: %2. Přijatá data zůstávají zachována, vyberte jiný soubor.</translation>
    </message>
    <message>
        <source>Saved %1 bytes to %2.</source>
        <translation>Uloženo %1 bajtů do %2.</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>%1 nelze přečíst: %2</translation>
    </message>
    <message>
        <source>%1 bytes; inner blocks: %2</source>
        <translation>%1 bajtů; vnitřní bloky: %2</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Přesto odeslat</translation>
    </message>
    <message>
        <source>Send a file whose inner blocks have a wrong checksum, or whose length this controller reported itself. Only for data the controller gave you.</source>
        <translation>Pošle soubor, jehož vnitřní bloky mají chybný kontrolní součet, nebo jehož délku hlásil sám tento řídicí systém. Jen pro data, která vám dal řídicí systém.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Zrušeno.</translation>
    </message>
    <message>
        <source>Cancelled: %1</source>
        <translation>Zrušeno: %1</translation>
    </message>
    <message>
        <source>Receiving from the controller failed</source>
        <translation>Příjem z řídicího systému selhal</translation>
    </message>
    <message>
        <source>Sending to the controller failed</source>
        <translation>Odeslání do řídicího systému selhalo</translation>
    </message>
    <message>
        <source>Transfer failed.</source>
        <translation>Přenos selhal.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 holds %2 data (saved from a %2 control): is the wrong system selected? Choose %2 and connect again. Nothing was sent.</source>
        <translation>%1 obsahuje data %2 (uložená z řídicího systému %2): není vybrán nesprávný systém? Zvolte %2 a připojte se znovu. Nic se neposlalo.</translation>
    </message>
    <message>
        <source>Frezka grinder file, keeps the header (*.frg);;Bare data for the old tools (*.bin)</source>
        <translation>Soubor Frezka pro brusky, uchová hlavičku (*.frg);;Holá data pro staré programy (*.bin)</translation>
    </message>
    <message>
        <source>%1 is damaged: %2</source>
        <translation>%1 je poškozený: %2</translation>
    </message>
    <message>
        <source>%1 bytes from the editor</source>
        <translation>%1 bajtů z editoru</translation>
    </message>
    <message>
        <source>ANC messages carry no header; nothing typed here would be sent.</source>
        <translation>Zprávy ANC nemají hlavičku; nic, co sem napíšete, by se neposlalo.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::UnitConfigDialog</name>
    <message>
        <source>No reply to %1 within 5 s.</source>
        <translation>Na %1 nepřišla do 5 s odpověď.</translation>
    </message>
    <message>
        <source>Reading the unit&apos;s EEPROM…</source>
        <translation>Čtu EEPROM jednotky…</translation>
    </message>
    <message>
        <source>The unit already matches the profile.</source>
        <translation>Jednotka již odpovídá profilu.</translation>
    </message>
    <message>
        <source>Read the unit first.</source>
        <translation>Nejprve načtěte jednotku.</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n setting(s) and reading them back…</source>
        <translation>
            <numerusform>Zapisuji %n nastavení a čtu je zpět…</numerusform>
            <numerusform>Zapisuji %n nastavení a čtu je zpět…</numerusform>
            <numerusform>Zapisuji %n nastavení a čtu je zpět…</numerusform>
        </translation>
    </message>
    <message>
        <source>The unit refused %1 (reply %2).</source>
        <translation>Jednotka odmítla %1 (odpověď %2).</translation>
    </message>
    <message>
        <source>Cannot read the value in the reply to %1: %2</source>
        <translation>V odpovědi na %1 nelze přečíst hodnotu: %2</translation>
    </message>
    <message>
        <source>Read-back of %1 gives %2, not the %3 written.</source>
        <translation>Zpětné čtení %1 vrací %2, ne zapsanou hodnotu %3.</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 selhalo: %2</translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation>Zatím nenačteno.</translation>
    </message>
    <message numerus="yes">
        <source>The unit matches the profile (%n setting(s) compared).</source>
        <translation>
            <numerusform>Jednotka odpovídá profilu (porovnáno %n nastavení).</numerusform>
            <numerusform>Jednotka odpovídá profilu (porovnána %n nastavení).</numerusform>
            <numerusform>Jednotka odpovídá profilu (porovnáno %n nastavení).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ from the profile.</source>
        <translation>
            <numerusform>%n nastavení se liší od profilu.</numerusform>
            <numerusform>%n nastavení se liší od profilu.</numerusform>
            <numerusform>%n nastavení se liší od profilu.</numerusform>
        </translation>
    </message>
    <message>
        <source>Unit configuration (EEPROM)</source>
        <translation>Konfigurace jednotky (EEPROM)</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresa</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Nastavení</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednotka</translation>
    </message>
    <message>
        <source>Meaning (unit value)</source>
        <translation>Význam (hodnota v jednotce)</translation>
    </message>
    <message>
        <source>Read from unit</source>
        <translation>Načíst z jednotky</translation>
    </message>
    <message>
        <source>Write differences</source>
        <translation>Zapsat rozdíly</translation>
    </message>
    <message>
        <source>Write all</source>
        <translation>Zapsat vše</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavřít</translation>
    </message>
    <message>
        <source>Write the unit&apos;s EEPROM</source>
        <translation>Zápis do EEPROM jednotky</translation>
    </message>
    <message numerus="yes">
        <source>Write all %n value(s) of the profile into the unit&apos;s EEPROM?</source>
        <translation>
            <numerusform>Zapsat %n hodnotu profilu do EEPROM jednotky?</numerusform>
            <numerusform>Zapsat všechny %n hodnoty profilu do EEPROM jednotky?</numerusform>
            <numerusform>Zapsat všech %n hodnot profilu do EEPROM jednotky?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write the %n value(s) that differ into the unit&apos;s EEPROM?</source>
        <translation>
            <numerusform>Zapsat %n odlišnou hodnotu do EEPROM jednotky?</numerusform>
            <numerusform>Zapsat %n odlišné hodnoty do EEPROM jednotky?</numerusform>
            <numerusform>Zapsat %n odlišných hodnot do EEPROM jednotky?</numerusform>
        </translation>
    </message>
    <message>
        <source>The unit keeps them after it is switched off, and the machine moves by them from now on.</source>
        <translation>Jednotka si je pamatuje i po vypnutí a stroj se jimi od teď řídí.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::UnitsPanel</name>
    <message>
        <source>%1 (this window&apos;s machine)</source>
        <translation>%1 (stroj tohoto okna)</translation>
    </message>
    <message>
        <source>none high</source>
        <translation>žádný v log. 1</translation>
    </message>
    <message>
        <source>high: %1</source>
        <translation>v log. 1: %1</translation>
    </message>
    <message>
        <source>all off</source>
        <translation>všechny vypnuté</translation>
    </message>
    <message>
        <source>on: %1</source>
        <translation>zapnuté: %1</translation>
    </message>
    <message>
        <source>Units on the line</source>
        <translation>Jednotky na lince</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresa</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednotka</translation>
    </message>
    <message>
        <source>Firmware · identity</source>
        <translation>Firmware · identita</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stav</translation>
    </message>
    <message>
        <source>X mm</source>
        <translation>X mm</translation>
    </message>
    <message>
        <source>Y mm</source>
        <translation>Y mm</translation>
    </message>
    <message>
        <source>Z mm</source>
        <translation>Z mm</translation>
    </message>
    <message>
        <source>A °</source>
        <translation>A °</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Vstupy</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Výstupy</translation>
    </message>
    <message>
        <source>Jog another unit:</source>
        <translation>Ruční pohyb jiné jednotky:</translation>
    </message>
    <message>
        <source>Step in mm (A: degrees)</source>
        <translation>Krok v mm (A: ve stupních)</translation>
    </message>
    <message>
        <source>Jog the chosen unit&apos;s axis by one step in the negative direction</source>
        <translation>Posunout zvolenou osu vybrané jednotky o jeden krok v záporném směru</translation>
    </message>
    <message>
        <source>Jog the chosen unit&apos;s axis by one step in the positive direction</source>
        <translation>Posunout zvolenou osu vybrané jednotky o jeden krok v kladném směru</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Stop the chosen unit: its jog ends, a job or homing is held</source>
        <translation>Zastavit vybranou jednotku: její ruční pohyb skončí, úloha nebo najíždění reference se pozastaví</translation>
    </message>
    <message>
        <source>Make it this window&apos;s machine</source>
        <translation>Udělat z ní stroj tohoto okna</translation>
    </message>
    <message>
        <source>The window then runs, jogs and shows the chosen unit with its own profile; possible while every unit on the line is idle</source>
        <translation>Okno pak spouští, posouvá a zobrazuje vybranou jednotku s jejím vlastním profilem; lze, jen když všechny jednotky na lince stojí</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ZPositionPanel</name>
    <message>
        <source>Read position (Z?)</source>
        <translation>Načíst polohu (Z?)</translation>
    </message>
    <message>
        <source>GO</source>
        <translation>JEĎ (GO)</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Move the table to this Z position (selector in PGN).</source>
        <translation>Přejet stolem do této polohy Z (přepínač v PGN).</translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation>Protokol:</translation>
    </message>
    <message>
        <source>Z position:</source>
        <translation>Poloha Z:</translation>
    </message>
    <message>
        <source>Go to:</source>
        <translation>Jet na:</translation>
    </message>
    <message>
        <source>not connected in a Z-position mode</source>
        <translation>není připojeno v režimu polohy Z</translation>
    </message>
    <message>
        <source>FORM=1: ASCII both ways (Z?, GO)</source>
        <translation>FORM=1: ASCII oběma směry (Z?, GO)</translation>
    </message>
    <message>
        <source>FORM=2: binary frames sent by the controller</source>
        <translation>FORM=2: binární rámce posílané řídicím systémem</translation>
    </message>
    <message>
        <source>%1 bytes skipped to find the frame start.</source>
        <translation>Přeskočeno %1 bajtů při hledání začátku rámce.</translation>
    </message>
    <message>
        <source>Asking for the position…</source>
        <translation>Zjišťuji polohu…</translation>
    </message>
    <message>
        <source>Moving to %1 mm…</source>
        <translation>Přejíždím na %1 mm…</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 frames received.</source>
        <translation>Přijato %1 rámců.</translation>
    </message>
    <message>
        <source>Position received at %1.</source>
        <translation>Poloha přijata v %1.</translation>
    </message>
</context>
<context>
    <name>frezka::gveemu</name>
    <message>
        <source>%1 needs a value (see --help)</source>
        <translation>%1 potřebuje hodnotu (viz --help)</translation>
    </message>
    <message>
        <source>unknown option %1 (see --help)</source>
        <translation>neznámá volba %1 (viz --help)</translation>
    </message>
    <message>
        <source>invalid value &apos;%1&apos; for %2 (see --help)</source>
        <translation>neplatná hodnota &apos;%1&apos; pro %2 (viz --help)</translation>
    </message>
    <message>
        <source>%1 Bd is not a baud rate of the %2</source>
        <translation>%1 Bd není přenosová rychlost jednotky %2</translation>
    </message>
    <message>
        <source>%1 pulses/s is not an orderable rate of the %2</source>
        <translation>%1 pulzů/s není objednatelná frekvence jednotky %2</translation>
    </message>
    <message>
        <source>the %1 has no axis A</source>
        <translation>%1 nemá osu A</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a firmware string of the %2</source>
        <translation>&apos;%1&apos; není řetězec firmwaru jednotky %2</translation>
    </message>
    <message>
        <source>cannot read the wheel turn &apos;%1&apos;: write AXIS STEP DETENTS, e.g. X 10 -5</source>
        <translation>otočení kolečka &apos;%1&apos; nelze přečíst: napište OSA KROK DÍLKY, např. X 10 -5</translation>
    </message>
    <message>
        <source>cannot read the unit &apos;%1&apos; of --units: write ADDRESS:VARIANT with an address 0..6, e.g. 0:gve114,1:gve114</source>
        <translation>jednotku &apos;%1&apos; ve volbě --units nelze přečíst: napište ADRESA:VARIANTA s adresou 0..6, např. 0:gve114,1:gve114</translation>
    </message>
    <message>
        <source>--units names address %1 twice: give each unit its own address</source>
        <translation>--units uvádí adresu %1 dvakrát: dejte každé jednotce vlastní adresu</translation>
    </message>
    <message>
        <source>Usage: gve-emu [options]
Serves an emulated GVE interpolator on a new pseudo-terminal in real time.
The first line printed on stdout is the terminal path to open (e.g. /dev/pts/5).
Stop it with Ctrl+C (SIGINT) or SIGTERM.

Options:
  --variant ID        gve84 | gve64 | gve64-phantom | gve114 (default gve64)
  --baud N            line speed, one of the variant&apos;s rates (default 115200)
  --max-rate N        maximum pulse rate of the unit, pulses/s (one of the
                      variant&apos;s orderable rates; default the variant&apos;s default)
  --firmware TEXT     the reply to &apos;?&apos;, e.g. &quot;IP64MPG v17 1.2.2009&quot;: an older
                      GVE64 firmware lacks MPG and EEPROM floats (v10), VK/VL/XM
                      and N&lt;axis&gt; (v19) (default the variant&apos;s)
  --bad-checksum-code N  reply code 0..7 to a command with a wrong checksum, for
                      testing a unit that differs from the adopted reading (4)
  --address N         unit address 0..6 (default 0)
  --units A:ID,...    several units on the one line, e.g. 0:gve114,1:gve114:
                      each answers only its address (0..6), all share the wire
                      and its time; address 7 (the spindle) is the first unit&apos;s
                      that has one; the other options apply to every unit
                      (--eeprom FILE keeps unit A&apos;s EEPROM in FILE.A)
  --latency MS        added delay each way, milliseconds (default 0)
  --latency-to-unit MS, --latency-to-pc MS   the same for one direction
  --seed N            seed of the fault injector (default 1)
  --corrupt P         probability per byte of a flipped bit, both ways (0..1)
  --drop P            probability per byte that it is lost, both ways
  --duplicate P       probability per byte that it arrives twice, both ways
  --lose-reply P      probability that a whole reply is lost
  --eeprom FILE       keep the EEPROM in FILE (read at start, written on EW/EFW/EUW)
  --home AXIS=POS[,+|-]   home switch of AXIS (X, Y, Z, A on IN0..IN3): it is
                      pressed at and below POS (-, default) or at and above (+)
  --limit IN:AXIS=POS[,+|-]  input IN (0..15) pressed by AXIS beyond POS, e.g.
                      --limit 6:X=200000,+ (GVE64 end switch X)
  --surface SPEC      the work&apos;s top, touched by the tool probe (IN15), in machine
                      mm: plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or
                      warp:Z0,DZDX,DZDY,AMP,PERIOD (the plane plus the sine)
  --steps-per-mm N[,N,N]  steps per mm of X, Y, Z for --surface (default 200)
  --probe-contact 0|1 the IN15 level at contact (default 0, as the shipped
                      profiles&apos; EEPROM polarity)
  --link PATH         also create a symlink PATH to the terminal
  --replay TRACE      answer as the unit recorded in TRACE did (a serial trace,
                      docs/serial-trace.md): each recorded reply when the driver
                      sends the command before it, with its timing; a command
                      that differs ends gve-emu with the trace line (exit 3)
  --com-switch N      the COM SPEED switch, 0..3 (sw1 sw2 OFF OFF .. ON ON): the
                      unit listens at its speed in the range of EEPROM 0x0D,
                      read at start; a client at another speed is not heard
                      (default: not modelled, any speed is heard)
  --analog-jumper ana|pwm  the board&apos;s ANA/PWM jumper (default ana)
  --wheel             turn the MPG handwheel from stdin, one line per turn:
                      AXIS STEP DETENTS, e.g. &quot;X 10 -5&quot; (AXIS X, Y, Z, A or 4,
                      STEP 1, 10 or 100; the unit moves by its EEPROM&apos;s MPG)
  --verbose           log every byte to stderr
  --help              this text
  --version           the version
</source>
        <translation>Použití: gve-emu [volby]
Obsluhuje emulovaný interpolátor GVE na novém pseudoterminálu v reálném čase.
První řádek na stdout je cesta k terminálu, který se má otevřít (např. /dev/pts/5).
Ukončí se pomocí Ctrl+C (SIGINT) nebo SIGTERM.

Volby:
  --variant ID        gve84 | gve64 | gve64-phantom | gve114 (výchozí gve64)
  --baud N            rychlost linky, jedna z rychlostí varianty (výchozí 115200)
  --max-rate N        nejvyšší frekvence pulzů jednotky, pulzy/s (jedna z
                      objednatelných frekvencí varianty; výchozí podle varianty)
  --firmware TEXT     odpověď na &apos;?&apos;, např. &quot;IP64MPG v17 1.2.2009&quot;: starší
                      firmware GVE64 nemá MPG a EEPROM float (v10), VK/VL/XM
                      a N&lt;osa&gt; (v19) (výchozí podle varianty)
  --bad-checksum-code N  kód odpovědi 0..7 na příkaz se špatným kontrolním součtem,
                      pro zkoušku jednotky, která se liší od přijatého výkladu (4)
  --address N         adresa jednotky 0..6 (výchozí 0)
  --units A:ID,...    několik jednotek na jedné lince, např. 0:gve114,1:gve114:
                      každá odpovídá jen na svou adresu (0..6), všechny sdílejí
                      vedení a jeho čas; adresa 7 (vřeteno) patří první jednotce,
                      která ji má; ostatní volby platí pro každou jednotku
                      (--eeprom SOUBOR uchová EEPROM jednotky A v SOUBOR.A)
  --latency MS        přidané zpoždění v každém směru, milisekundy (výchozí 0)
  --latency-to-unit MS, --latency-to-pc MS   totéž pro jeden směr
  --seed N            semínko generátoru poruch (výchozí 1)
  --corrupt P         pravděpodobnost převráceného bitu na bajt, oba směry (0..1)
  --drop P            pravděpodobnost ztráty bajtu, oba směry
  --duplicate P       pravděpodobnost, že bajt dorazí dvakrát, oba směry
  --lose-reply P      pravděpodobnost ztráty celé odpovědi
  --eeprom SOUBOR     EEPROM uchovávat v SOUBORU (čte se při startu, zapisuje při EW/EFW/EUW)
  --home OSA=POLOHA[,+|-]   referenční spínač OSY (X, Y, Z, A na IN0..IN3): je
                      sepnut na POLOZE a pod ní (-, výchozí) nebo na ní a nad ní (+)
  --limit IN:OSA=POLOHA[,+|-]  vstup IN (0..15) sepnutý OSOU za POLOHOU, např.
                      --limit 6:X=200000,+ (koncový spínač X u GVE64)
  --surface POPIS     horní plocha obrobku, které se dotkne sonda nástroje (IN15),
                      v mm stroje: plane:Z0,DZDX,DZDY, sine:AMP,PERIODA[,Z0] nebo
                      warp:Z0,DZDX,DZDY,AMP,PERIODA (rovina plus sinus)
  --steps-per-mm N[,N,N]  kroky na mm os X, Y, Z pro --surface (výchozí 200)
  --probe-contact 0|1 úroveň IN15 při dotyku (výchozí 0, jako polarita EEPROM
                      dodávaných profilů)
  --link CESTA        vytvořit také symbolický odkaz CESTA na terminál
  --replay ZÁZNAM     odpovídat tak, jak odpovídala jednotka v ZÁZNAMU (sériový
                      záznam, docs/serial-trace.md): každou zaznamenanou odpověď,
                      když ovladač pošle příkaz před ní, s jejím časováním; jiný
                      příkaz ukončí gve-emu s řádkem záznamu (kód 3)
  --com-switch N      přepínač COM SPEED, 0..3 (sw1 sw2 OFF OFF .. ON ON): jednotka
                      poslouchá jeho rychlostí v rozsahu podle EEPROM 0x0D,
                      čtené při startu; klienta s jinou rychlostí neslyší
                      (výchozí: nemodelováno, slyší každou rychlost)
  --analog-jumper ana|pwm  propojka ANA/PWM na desce (výchozí ana)
  --wheel             otáčet ručním kolečkem MPG ze stdin, jeden řádek na otočení:
                      OSA KROK DÍLKY, např. &quot;X 10 -5&quot; (OSA X, Y, Z, A nebo 4,
                      KROK 1, 10 nebo 100; jednotka jede podle MPG ve své EEPROM)
  --verbose           vypisovat každý bajt na stderr
  --help              tento text
  --version           verze
</translation>
    </message>
</context>
<context>
    <name>frezka::session</name>
    <message>
        <source>held</source>
        <translation>platí</translation>
    </message>
    <message>
        <source>did not hold</source>
        <translation>neplatí</translation>
    </message>
    <message>
        <source>not checked</source>
        <translation>neověřeno</translation>
    </message>
    <message>
        <source>skipped</source>
        <translation>přeskočeno</translation>
    </message>
    <message>
        <source>Identify the unit</source>
        <translation>Identifikovat jednotku</translation>
    </message>
    <message>
        <source>Asks the unit for its firmware (?) and its number (Q) and compares them with the profile.</source>
        <translation>Zeptá se jednotky na firmware (?) a číslo (Q) a porovná je s profilem.</translation>
    </message>
    <message>
        <source>Check the protocol readings</source>
        <translation>Ověřit výklady protokolu</translation>
    </message>
    <message>
        <source>Checks the readings of the manuals that can be checked without motion: checksums, @ and &gt;, packet replies, error replies, EEPROM reads.</source>
        <translation>Ověří výklady manuálů, které lze ověřit bez pohybu: kontrolní součty, @ a &gt;, odpovědi na pakety, chybové odpovědi, čtení EEPROM.</translation>
    </message>
    <message>
        <source>Measure the link</source>
        <translation>Změřit linku</translation>
    </message>
    <message>
        <source>Times round trips per command class, the bytes per second and the adapter&apos;s latency, and proposes link.latencyMs.</source>
        <translation>Změří dobu odezvy podle druhu příkazu, bajty za sekundu a zpoždění převodníku a navrhne link.latencyMs.</translation>
    </message>
    <message>
        <source>Read the EEPROM</source>
        <translation>Přečíst EEPROM</translation>
    </message>
    <message>
        <source>Reads the unit&apos;s EEPROM settings, decodes them and compares them with the profile (nothing is written).</source>
        <translation>Přečte nastavení v EEPROM jednotky, dekóduje je a porovná s profilem (nic se nezapisuje).</translation>
    </message>
    <message>
        <source>Move axis %1</source>
        <translation>Pohnout osou %1</translation>
    </message>
    <message>
        <source>Moves axis %1 a little in + and then back in − at a low speed; you confirm the direction and enter the distance you measured, which corrects its steps per mm.</source>
        <translation>Pohne osou %1 malou rychlostí kousek v + a pak zpět v −; potvrdíte směr a zadáte naměřenou vzdálenost, podle které se opraví její kroky na mm.</translation>
    </message>
    <message>
        <source>Test the home and limit switches</source>
        <translation>Vyzkoušet referenční a koncové spínače</translation>
    </message>
    <message>
        <source>You press each switch by hand; the step watches its input.</source>
        <translation>Každý spínač stisknete rukou; krok sleduje jeho vstup.</translation>
    </message>
    <message>
        <source>Test the STOP button</source>
        <translation>Vyzkoušet tlačítko STOP</translation>
    </message>
    <message>
        <source>You press the STOP button; the step watches its input.</source>
        <translation>Stisknete tlačítko STOP; krok sleduje jeho vstup.</translation>
    </message>
    <message>
        <source>Run the spindle at two speeds</source>
        <translation>Roztočit vřeteno na dvě rychlosti</translation>
    </message>
    <message>
        <source>Switches the spindle on at a quarter and at half of its maximum speed, then off; you confirm it turned.</source>
        <translation>Zapne vřeteno na čtvrtinu a na polovinu nejvyšších otáček a pak ho vypne; potvrdíte, že se točilo.</translation>
    </message>
    <message>
        <source>Switch the outputs</source>
        <translation>Přepnout výstupy</translation>
    </message>
    <message>
        <source>Switches each output the profile uses (coolant, air ...) on and off; you confirm it switched.</source>
        <translation>Zapne a vypne každý výstup, který profil používá (chlazení, vzduch …); potvrdíte, že sepnul.</translation>
    </message>
    <message>
        <source>Home the machine</source>
        <translation>Referovat stroj</translation>
    </message>
    <message>
        <source>Homes the axes the profile homes, in its order (last, when the switches are known to work).</source>
        <translation>Zreferuje osy, které profil referuje, v jeho pořadí (nakonec, když je ověřeno, že spínače fungují).</translation>
    </message>
    <message>
        <source>+ move: %1 steps counted</source>
        <translation>pohyb +: napočítáno %1 kroků</translation>
    </message>
    <message>
        <source>(the axis did not move: at its soft limit, or the driver refused it)</source>
        <translation>(osa se nepohnula: je na softwarovém limitu, nebo ovladač pohyb odmítl)</translation>
    </message>
    <message>
        <source>Did axis %1 move in + (by about %2 mm)?</source>
        <translation>Pohnula se osa %1 v + (asi o %2 mm)?</translation>
    </message>
    <message>
        <source>How far did axis %1 move, measured in mm? (empty: as asked)</source>
        <translation>O kolik se osa %1 posunula, naměřeno v mm? (prázdné: jak bylo zadáno)</translation>
    </message>
    <message>
        <source>− move: %1 steps counted</source>
        <translation>pohyb −: napočítáno %1 kroků</translation>
    </message>
    <message>
        <source>Did axis %1 move back in −?</source>
        <translation>Vrátila se osa %1 zpět v −?</translation>
    </message>
    <message>
        <source>steps per mm %1 -&gt; %2</source>
        <translation>kroky na mm %1 -&gt; %2</translation>
    </message>
    <message>
        <source>Press the home switch of %1 (IN%2) now.</source>
        <translation>Stiskněte teď referenční spínač osy %1 (IN%2).</translation>
    </message>
    <message>
        <source>home %1 (IN%2): %3</source>
        <translation>reference %1 (IN%2): %3</translation>
    </message>
    <message>
        <source>the profile homes no axis</source>
        <translation>profil nereferuje žádnou osu</translation>
    </message>
    <message>
        <source>Press the STOP button (IN7) now.</source>
        <translation>Stiskněte teď tlačítko STOP (IN7).</translation>
    </message>
    <message>
        <source>IN7 changed when the button was pressed</source>
        <translation>IN7 se při stisku tlačítka změnil</translation>
    </message>
    <message>
        <source>IN7 did not change within %1 s: check the button&apos;s wiring</source>
        <translation>IN7 se do %1 s nezměnil: zkontrolujte zapojení tlačítka</translation>
    </message>
    <message>
        <source>Does the spindle turn at about %1 rpm?</source>
        <translation>Točí se vřeteno asi na %1 ot/min?</translation>
    </message>
    <message>
        <source>%1 rpm (%2 ‰): %3</source>
        <translation>%1 ot/min (%2 ‰): %3</translation>
    </message>
    <message>
        <source>Did OUT%1 switch on?</source>
        <translation>Sepnul výstup OUT%1?</translation>
    </message>
    <message>
        <source>OUT%1: %2</source>
        <translation>OUT%1: %2</translation>
    </message>
    <message>
        <source>the profile uses no output</source>
        <translation>profil nepoužívá žádný výstup</translation>
    </message>
    <message>
        <source>every axis the profile homes was homed</source>
        <translation>všechny osy, které profil referuje, jsou zreferované</translation>
    </message>
    <message>
        <source>homing did not finish: %1</source>
        <translation>referování neskončilo: %1</translation>
    </message>
    <message>
        <source>no error reported</source>
        <translation>žádná chyba nebyla hlášena</translation>
    </message>
    <message>
        <source>the driver could not connect: %1</source>
        <translation>ovladač se nemohl připojit: %1</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>bez odpovědi</translation>
    </message>
    <message>
        <source>skipped by the operator</source>
        <translation>přeskočeno obsluhou</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednotka</translation>
    </message>
    <message>
        <source>port: %1
</source>
        <translation>port: %1
</translation>
    </message>
    <message>
        <source>identified as: %1
</source>
        <translation>identifikována jako: %1
</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>neznámá</translation>
    </message>
    <message>
        <source>firmware: %1
</source>
        <translation>firmware: %1
</translation>
    </message>
    <message>
        <source>(no answer)</source>
        <translation>(bez odpovědi)</translation>
    </message>
    <message>
        <source>unit number: %1
</source>
        <translation>číslo jednotky: %1
</translation>
    </message>
    <message>
        <source>profile: %1 (%2, firmware v%3)
</source>
        <translation>profil: %1 (%2, firmware v%3)
</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Kroky</translation>
    </message>
    <message>
        <source> (moves)</source>
        <translation> (pohybuje)</translation>
    </message>
    <message>
        <source>Protocol readings (docs/gve-protocol.md)</source>
        <translation>Výklady protokolu (docs/gve-protocol.md)</translation>
    </message>
    <message>
        <source>none checked
</source>
        <translation>nic neověřeno
</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Linka</translation>
    </message>
    <message>
        <source>baud: %1
</source>
        <translation>baud: %1
</translation>
    </message>
    <message>
        <source>%1 %2: %3 samples, %4 bytes each, round trip min %5 ms, median %6 ms, max %7 ms
</source>
        <translation>%1 %2: %3 vzorků, %4 bajtů každý, odezva min %5 ms, medián %6 ms, max %7 ms
</translation>
    </message>
    <message>
        <source>bytes/s in packets (both ways): %1
</source>
        <translation>bajty/s v paketech (oba směry): %1
</translation>
    </message>
    <message>
        <source>estimated adapter latency, one way: %1 ms
</source>
        <translation>odhadnuté zpoždění převodníku, jeden směr: %1 ms
</translation>
    </message>
    <message>
        <source>link.latencyMs: profile %1, proposed %2
</source>
        <translation>link.latencyMs: profil %1, návrh %2
</translation>
    </message>
    <message>
        <source>EEPROM (decoded, against the profile)</source>
        <translation>EEPROM (dekódovaná, proti profilu)</translation>
    </message>
    <message>
        <source>not read
</source>
        <translation>nepřečteno
</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nepřečteno</translation>
    </message>
    <message>
        <source>0x%1 %2: unit %3, profile %4 - %5
</source>
        <translation>0x%1 %2: jednotka %3, profil %4 - %5
</translation>
    </message>
    <message>
        <source>same</source>
        <translation>shodné</translation>
    </message>
    <message>
        <source>differs</source>
        <translation>liší se</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation>Osy</translation>
    </message>
    <message>
        <source>no axis was moved
</source>
        <translation>žádnou osou se nepohnulo
</translation>
    </message>
    <message>
        <source>%1: + %2, − %3, moved %4 mm each way, steps/mm %5</source>
        <translation>%1: + %2, − %3, posun %4 mm každým směrem, kroky/mm %5</translation>
    </message>
    <message>
        <source>, measured %1 mm</source>
        <translation>, naměřeno %1 mm</translation>
    </message>
    <message>
        <source>, proposed steps/mm %1</source>
        <translation>, navržené kroky/mm %1</translation>
    </message>
    <message>
        <source>Frezka commissioning report
===========================
</source>
        <translation>Protokol o uvedení do provozu (Frezka)
======================================
</translation>
    </message>
    <message>
        <source>Serial trace (docs/serial-trace.md)</source>
        <translation>Záznam sériové linky (docs/serial-trace.md)</translation>
    </message>
    <message>
        <source>not recorded
</source>
        <translation>nezaznamenáno
</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>nelze zapsat %1: %2</translation>
    </message>
    <message>
        <source>the updated profile would replace %1; name a new file (--profile-out)</source>
        <translation>upravený profil by přepsal %1; zadejte nový soubor (--profile-out)</translation>
    </message>
    <message>
        <source>%+ switches checksums on and its reply already carries one (0,5C)</source>
        <translation>%+ zapne kontrolní součty a už jeho odpověď jeden nese (0,5C)</translation>
    </message>
    <message>
        <source>a command with a wrong checksum is answered 4 and does not advance the index (@)</source>
        <translation>na příkaz se špatným kontrolním součtem jednotka odpoví 4 a nezvýší index (@)</translation>
    </message>
    <message>
        <source>every valid command advances the index by one, @ itself does not</source>
        <translation>každý platný příkaz zvýší index o jedna, @ sám ne</translation>
    </message>
    <message>
        <source>&gt; repeats the last reply without executing the command again</source>
        <translation>&gt; zopakuje poslední odpověď, aniž by příkaz znovu provedl</translation>
    </message>
    <message>
        <source>an unknown command is answered 3</source>
        <translation>na neznámý příkaz jednotka odpoví 3</translation>
    </message>
    <message>
        <source>a malformed parameter is answered 4</source>
        <translation>na chybně zapsaný parametr jednotka odpoví 4</translation>
    </message>
    <message>
        <source>a parameter out of range is answered 5 (T99)</source>
        <translation>na parametr mimo rozsah jednotka odpoví 5 (T99)</translation>
    </message>
    <message>
        <source>a LF after the CR is ignored</source>
        <translation>LF za CR se ignoruje</translation>
    </message>
    <message>
        <source>a packet is answered once, at its end, with the number of commands (0,2)</source>
        <translation>na paket jednotka odpoví jednou, na jeho konci, počtem příkazů (0,2)</translation>
    </message>
    <message>
        <source>a packet whose command fails stops there and answers that code and the number accepted before it (5,1)</source>
        <translation>paket, jehož příkaz selže, se tam zastaví a odpoví kódem chyby a počtem příkazů přijatých před ním (5,1)</translation>
    </message>
    <message>
        <source>a 4-axis unit takes L with three components (A = 0); fewer than three is answered 4</source>
        <translation>čtyřosá jednotka přijme L se třemi složkami (A = 0); na méně než tři odpoví 4</translation>
    </message>
    <message>
        <source>a 3-axis unit answers 4 to a vector of four components or of two</source>
        <translation>tříosá jednotka odpoví 4 na vektor se čtyřmi nebo dvěma složkami</translation>
    </message>
    <message>
        <source>ERaa reads an EEPROM byte as two hex digits</source>
        <translation>ERaa čte bajt EEPROM jako dvě šestnáctkové číslice</translation>
    </message>
    <message>
        <source>float and 32-bit EEPROM values travel as decimal text</source>
        <translation>hodnoty EEPROM typu float a 32bitové se přenášejí jako desítkový text</translation>
    </message>
    <message>
        <source>the unit&apos;s firmware has no EFR/EUR</source>
        <translation>firmware jednotky nemá EFR/EUR</translation>
    </message>
    <message>
        <source>needs motion or a reset; not checked here</source>
        <translation>vyžaduje pohyb nebo reset; zde neověřeno</translation>
    </message>
    <message>
        <source>the speed mode after a reset is VN</source>
        <translation>po resetu je režim rychlosti VN</translation>
    </message>
    <message>
        <source>VL limits are in pulses/s</source>
        <translation>limity VL jsou v pulzech/s</translation>
    </message>
    <message>
        <source>a home switch not found within the travel is answered 5</source>
        <translation>na referenční spínač nenalezený v rámci dráhy jednotka odpoví 5</translation>
    </message>
    <message>
        <source>the homing step shows it</source>
        <translation>ukáže to krok referování</translation>
    </message>
    <message>
        <source>%1 readings held, %2 did not hold, %3 not checked.</source>
        <translation>%1 výkladů platí, %2 neplatí, %3 neověřeno.</translation>
    </message>
    <message>
        <source>Send the report (README: when a unit does something unexpected).</source>
        <translation>Pošlete protokol (README: když jednotka dělá něco neočekávaného).</translation>
    </message>
    <message>
        <source>The unit did not answer &apos;?&apos; (%1). Check the cable, the port and the baud rate set on the unit.</source>
        <translation>Jednotka neodpověděla na &apos;?&apos; (%1). Zkontrolujte kabel, port a rychlost nastavenou na jednotce.</translation>
    </message>
    <message>
        <source>the firmware &apos;%1&apos; names no known unit</source>
        <translation>firmware &apos;%1&apos; neoznačuje žádnou známou jednotku</translation>
    </message>
    <message>
        <source>the unit is a %1, the profile is for a %2</source>
        <translation>jednotka je %1, profil je pro %2</translation>
    </message>
    <message>
        <source>the firmware is v%1, the profile says v%2 (unit.firmwareVersion)</source>
        <translation>firmware je v%1, profil uvádí v%2 (unit.firmwareVersion)</translation>
    </message>
    <message>
        <source>Firmware &apos;%1&apos;, unit number &apos;%2&apos;.</source>
        <translation>Firmware &apos;%1&apos;, číslo jednotky &apos;%2&apos;.</translation>
    </message>
    <message>
        <source>. Correct the profile (unit.variant, unit.firmwareVersion) to the unit.</source>
        <translation>. Opravte profil (unit.variant, unit.firmwareVersion) podle jednotky.</translation>
    </message>
    <message>
        <source>status (F)</source>
        <translation>stav (F)</translation>
    </message>
    <message>
        <source>position (PF/P4)</source>
        <translation>poloha (PF/P4)</translation>
    </message>
    <message>
        <source>EEPROM byte (ER)</source>
        <translation>bajt EEPROM (ER)</translation>
    </message>
    <message>
        <source>packet of 10 B</source>
        <translation>paket 10× B</translation>
    </message>
    <message>
        <source>The unit did not answer the timed commands.</source>
        <translation>Jednotka neodpověděla na měřené příkazy.</translation>
    </message>
    <message>
        <source>Adapter latency about %1 ms each way; %2 bytes/s in packets; proposed link.latencyMs = %3 (the profile had %4).</source>
        <translation>Zpoždění převodníku asi %1 ms každým směrem; %2 bajtů/s v paketech; navržené link.latencyMs = %3 (profil měl %4).</translation>
    </message>
    <message>
        <source>The link is slower than the profile says: the planner would pace jobs for a faster line. Save the proposed profile.</source>
        <translation>Linka je pomalejší, než uvádí profil: plánovač by úlohy dávkoval pro rychlejší linku. Uložte navržený profil.</translation>
    </message>
    <message>
        <source>not on this firmware</source>
        <translation>u tohoto firmwaru není</translation>
    </message>
    <message>
        <source>%1 settings read, %2 differ from the profile, %3 could not be read.</source>
        <translation>%1 nastavení přečteno, %2 se liší od profilu, %3 nelze přečíst.</translation>
    </message>
    <message>
        <source>Write the profile&apos;s values with Machine › Unit configuration (EEPROM), or correct the profile.</source>
        <translation>Zapište hodnoty profilu přes Stroj › Konfigurace jednotky (EEPROM), nebo opravte profil.</translation>
    </message>
    <message>
        <source>The unit was not identified.</source>
        <translation>Jednotka nebyla identifikována.</translation>
    </message>
    <message>
        <source>The machine profile has no tool length sensor: set its position and probing in Machine › Settings (Tools › Tool length sensor), then measure again.</source>
        <translation>Profil stroje nemá snímač délky nástroje: nastavte jeho polohu a sondování v Stroj › Nastavení (Nástroje › Snímač délky nástroje) a pak měřte znovu.</translation>
    </message>
</context>
<context>
    <name>frezka::session::ConsoleSession</name>
    <message>
        <source>Manual G-code runs only while the machine is ready.</source>
        <translation>Ruční G-kód lze spustit jen tehdy, když je stroj připraven.</translation>
    </message>
    <message>
        <source>manual line</source>
        <translation>ruční řádek</translation>
    </message>
    <message>
        <source>Manual: %1 (%2)</source>
        <translation>Ručně: %1 (%2)</translation>
    </message>
</context>
<context>
    <name>frezka::session::HeightProbe</name>
    <message>
        <source>The area to probe is empty (X %1 to %2, Y %3 to %4): give its corners with X0 &lt; X1 and Y0 &lt; Y1.</source>
        <translation>Oblast sondování je prázdná (X %1 až %2, Y %3 až %4): zadejte její rohy tak, aby X0 &lt; X1 a Y0 &lt; Y1.</translation>
    </message>
    <message>
        <source>The spacing of the grid must be above 0 mm (%1 given).</source>
        <translation>Rozteč mřížky musí být větší než 0 mm (zadáno %1).</translation>
    </message>
    <message>
        <source>The probing feed must be above 0 mm/min (%1 given).</source>
        <translation>Posuv sondování musí být větší než 0 mm/min (zadáno %1).</translation>
    </message>
    <message>
        <source>The probe&apos;s lowest Z (%1) must be below the clearance height (%2): give a depth above 0 mm.</source>
        <translation>Nejnižší Z sondy (%1) musí být pod bezpečnou výškou (%2): zadejte hloubku větší než 0 mm.</translation>
    </message>
    <message>
        <source>A spacing of %1 mm gives %2 x %3 points to probe (at most %4): choose a larger spacing or a smaller area.</source>
        <translation>Rozteč %1 mm dává %2 x %3 bodů k sondování (nejvýše %4): zvolte větší rozteč nebo menší oblast.</translation>
    </message>
    <message>
        <source>Probing is already running.</source>
        <translation>Sondování už běží.</translation>
    </message>
    <message>
        <source>The machine is not ready to probe (%1): connect it and wait until it is idle, then probe again.</source>
        <translation>Stroj není připraven k sondování (%1): připojte ho, počkejte, až bude v klidu, a sondujte znovu.</translation>
    </message>
    <message>
        <source>Probing cancelled after %1 of %2 points; the tool goes up to the clearance.</source>
        <translation>Sondování zrušeno po %1 z %2 bodů; nástroj vyjede do bezpečné výšky.</translation>
    </message>
    <message>
        <source>X %1, Y %2</source>
        <translation>X %1, Y %2</translation>
    </message>
    <message>
        <source>probing</source>
        <translation>sondování</translation>
    </message>
    <message>
        <source>The move to probe at %1 cannot be planned: %2</source>
        <translation>Pohyb k sondování v bodě %1 nelze naplánovat: %2</translation>
    </message>
    <message>
        <source>The link to the machine was lost while probing at %1: probe the grid again once it is connected.</source>
        <translation>Spojení se strojem se ztratilo při sondování v bodě %1: po opětovném připojení mřížku nasondujte znovu.</translation>
    </message>
    <message>
        <source>The probe at %1 went down to Z %2 without touching the surface: the work is lower than the depth allows, or the probe is not connected. Check the probe and the clearance, or probe again with a larger depth.</source>
        <translation>Sonda v bodě %1 sjela až na Z %2, aniž se dotkla povrchu: obrobek je níž, než hloubka dovoluje, nebo sonda není připojena. Zkontrolujte sondu a bezpečnou výšku, nebo sondujte znovu s větší hloubkou.</translation>
    </message>
    <message>
        <source>The probe at %1 was already in contact before moving down: check the probe and its wiring, and that the tool is clear of the work.</source>
        <translation>Sonda v bodě %1 byla v kontaktu už před pohybem dolů: zkontrolujte sondu a její zapojení a zda nástroj nepřekáží obrobku.</translation>
    </message>
    <message>
        <source>Probing at %1 stopped: %2</source>
        <translation>Sondování v bodě %1 se zastavilo: %2</translation>
    </message>
    <message>
        <source>the job did not finish.</source>
        <translation>úloha nedoběhla.</translation>
    </message>
    <message>
        <source>Probing fast then slow needs a retract above 0 mm (%1 given): the tool backs off by it before the slow probe.</source>
        <translation>Sondování rychle a pak pomalu potřebuje odjetí větší než 0 mm (zadáno %1): o ně nástroj odjede před pomalým sondováním.</translation>
    </message>
    <message>
        <source>An edge is probed along X or Y, in the + or - direction.</source>
        <translation>Hrana se sonduje podél X nebo Y, ve směru + nebo -.</translation>
    </message>
    <message>
        <source>The probe&apos;s travel toward the edge must be above 0 mm (%1 given).</source>
        <translation>Dráha sondy k hraně musí být větší než 0 mm (zadáno %1).</translation>
    </message>
    <message>
        <source>The probe moved from %1 %2 to %1 %3 without touching the edge: the edge is farther than the travel, or the probe is not connected. Check the probe and where the tool stands (beside the edge, below the work&apos;s top), or probe again with a longer travel.</source>
        <translation>Sonda dojela z %1 %2 do %1 %3, aniž by se dotkla hrany: hrana je dál, než dovoluje dráha, nebo sonda není připojena. Zkontrolujte sondu a kde nástroj stojí (vedle hrany, pod horní plochou obrobku), nebo sondujte znovu s delší dráhou.</translation>
    </message>
    <message>
        <source>The spindle is turning: stop it (M5 or the spindle button) before probing. A probe or a sensor touched by a turning tool breaks one of them.</source>
        <translation>Vřeteno se točí: před sondováním ho zastavte (M5 nebo tlačítkem vřetena). Sonda nebo čidlo, kterého se dotkne točící se nástroj, se zničí – nebo nástroj.</translation>
    </message>
</context>
<context>
    <name>frezka::session::ProgramSession</name>
    <message>
        <source>Reading</source>
        <translation>Čtení</translation>
    </message>
    <message>
        <source>Indexing lines</source>
        <translation>Indexování řádků</translation>
    </message>
    <message>
        <source>Interpreting</source>
        <translation>Interpretace</translation>
    </message>
    <message>
        <source>Preparing the view</source>
        <translation>Příprava zobrazení</translation>
    </message>
    <message>
        <source>Planning</source>
        <translation>Plánování</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 nelze otevřít: %2</translation>
    </message>
    <message>
        <source>Line %1: after this line the path depends on the probe&apos;s result; it is shown as provisional, and each part is planned and run once the probe before it has run.</source>
        <translation>Řádek %1: za tímto řádkem závisí dráha na výsledku sondy; zobrazuje se jako předběžná a každá část se naplánuje a spustí, až proběhne sonda před ní.</translation>
    </message>
</context>
<context>
    <name>frezka::session::RunWorkflow</name>
    <message>
        <source>Not connected</source>
        <translation>Nepřipojeno</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Připojuji…</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Připraveno</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Najíždění do reference</translation>
    </message>
    <message>
        <source>Jogging</source>
        <translation>Ruční pohyb</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Obrábění</translation>
    </message>
    <message>
        <source>Stopping</source>
        <translation>Zastavuji</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pozastaveno</translation>
    </message>
    <message>
        <source>Tool lifted</source>
        <translation>Nástroj zvednut</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Spojení ztraceno</translation>
    </message>
    <message>
        <source>Connecting to %1 at %2 Bd…</source>
        <translation>Připojuji se k %1 rychlostí %2 Bd…</translation>
    </message>
    <message>
        <source>the built-in emulator</source>
        <translation>vestavěnému emulátoru</translation>
    </message>
    <message>
        <source>Open a program first.</source>
        <translation>Nejprve otevřete program.</translation>
    </message>
    <message>
        <source>The program has errors and cannot run:
%1</source>
        <translation>Program obsahuje chyby a nelze jej spustit:
%1</translation>
    </message>
    <message>
        <source>The machine is not ready (%1); wait until it is, then Run.</source>
        <translation>Stroj není připraven (%1); počkejte a pak stiskněte Spustit.</translation>
    </message>
    <message>
        <source>Planning from the current position…</source>
        <translation>Plánuji od současné polohy…</translation>
    </message>
    <message>
        <source>Running %1.</source>
        <translation>Obrábím %1.</translation>
    </message>
    <message>
        <source>the machine stopped: %1</source>
        <translation>stroj se zastavil: %1</translation>
    </message>
    <message>
        <source>the job stopped: %1</source>
        <translation>úloha se zastavila: %1</translation>
    </message>
    <message>
        <source>homing did not finish</source>
        <translation>najíždění do reference nedoběhlo</translation>
    </message>
    <message>
        <source> [command %1]</source>
        <translation> [příkaz %1]</translation>
    </message>
    <message>
        <source> [reply &apos;%1&apos;]</source>
        <translation> [odpověď &apos;%1&apos;]</translation>
    </message>
    <message>
        <source>the job did not finish</source>
        <translation>úloha nedoběhla</translation>
    </message>
    <message>
        <source>The machine is not homed: home it first, then Run.</source>
        <translation>Stroj není v referenci: nejprve jej najeďte do reference, pak stiskněte Spustit.</translation>
    </message>
    <message>
        <source>Warning: the machine is not homed; the program runs from counters that were not set by homing (motion.runBeforeHoming).</source>
        <translation>Varování: stroj není v referenci; program poběží podle čítačů, které nenastavilo najetí do reference (motion.runBeforeHoming).</translation>
    </message>
    <message>
        <source>Homing, then running the program…</source>
        <translation>Najíždím do reference, pak spustím program…</translation>
    </message>
    <message>
        <source>Homing did not finish; the program was not started.</source>
        <translation>Najíždění do reference nedoběhlo; program nebyl spuštěn.</translation>
    </message>
    <message>
        <source>START button: resuming the job.</source>
        <translation>Tlačítko START: pokračuji v úloze.</translation>
    </message>
    <message>
        <source>START button: running %1.</source>
        <translation>Tlačítko START: spouštím %1.</translation>
    </message>
    <message>
        <source>START button ignored: nothing to start or resume (%1).</source>
        <translation>Tlačítko START přeskočeno: není co spustit ani v čem pokračovat (%1).</translation>
    </message>
    <message>
        <source>%1: continuing without an operator.</source>
        <translation>%1: pokračuje se bez obsluhy.</translation>
    </message>
    <message>
        <source>Line %1: the probe touched at X %2 Y %3 Z %4 (machine); the rest of the program runs as interpreted with that result.</source>
        <translation>Řádek %1: sonda se dotkla v X %2 Y %3 Z %4 (strojní souřadnice); zbytek programu běží podle tohoto výsledku.</translation>
    </message>
    <message>
        <source>Line %1: the probe stopped at X %2 Y %3 Z %4 (machine) without touching; the rest of the program runs as interpreted with that result.</source>
        <translation>Řádek %1: sonda se zastavila v X %2 Y %3 Z %4 (strojní souřadnice) bez dotyku; zbytek programu běží podle tohoto výsledku.</translation>
    </message>
</context>
<context>
    <name>gve-emu</name>
    <message>
        <source>cannot create a pipe</source>
        <translation>nelze vytvořit rouru</translation>
    </message>
    <message>
        <source>cannot create the link %1</source>
        <translation>nelze vytvořit odkaz %1</translation>
    </message>
    <message>
        <source>cannot create the pseudo-terminal (%1): %2</source>
        <translation>nelze vytvořit pseudoterminál (%1): %2</translation>
    </message>
    <message>
        <source>cannot read the trace %1: %2</source>
        <translation>záznam %1 nelze přečíst: %2</translation>
    </message>
    <message>
        <source>the trace was played to its end; further commands get no reply</source>
        <translation>záznam byl přehrán do konce; další příkazy nedostanou odpověď</translation>
    </message>
    <message>
        <source>the wheel does nothing: the MPG is off (Y-), not enabled in the EEPROM (0x06 and its parameters) or an interrupt waits for G</source>
        <translation>kolečko nic nedělá: MPG je vypnuté (Y-), není povolené v EEPROM (0x06 a jeho parametry) nebo přerušení čeká na G</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Frezka: runs CNC mills through GVE interpolators.</source>
        <translation>Frezka: řídí CNC frézky přes interpolátory GVE.</translation>
    </message>
    <message>
        <source>Draw the toolpath without OpenGL.</source>
        <translation>Kreslit dráhu nástroje bez OpenGL.</translation>
    </message>
    <message>
        <source>Save the window as PNG once the program has loaded, then quit (README screenshots).</source>
        <translation>Po načtení programu uložit okno jako PNG a skončit (snímky pro README).</translation>
    </message>
    <message>
        <source>G-code program to open.</source>
        <translation>Program v G-kódu k otevření.</translation>
    </message>
    <message>
        <source>User interface language: cs or en (default: the settings, else the system language).</source>
        <translation>Jazyk uživatelského rozhraní: cs nebo en (výchozí: podle nastavení, jinak jazyk systému).</translation>
    </message>
    <message>
        <source>With --screenshot: home, run the program and take the screenshot after this many seconds of running.</source>
        <translation>S --screenshot: najet do reference, spustit program a pořídit snímek po tolika sekundách běhu.</translation>
    </message>
    <message>
        <source>With --screenshot: show this dock in front of the others (its object name, such as unitsDock).</source>
        <translation>S --screenshot: zobrazit tento panel před ostatními (jeho jméno objektu, např. unitsDock).</translation>
    </message>
    <message>
        <source>Apply this height map file to the program (as Machine › Height map › Apply, the work zero left as it is).</source>
        <translation>Použít tento soubor výškové mapy na program (jako Stroj › Výšková mapa › Použít na program; nulový bod obrobku zůstane, jak je).</translation>
    </message>
    <message>
        <source>real (default): the machine in real time; virtual: the built-in emulator on a virtual clock, as fast as the computer allows (a port is refused).</source>
        <translation>real (výchozí): stroj ve skutečném čase; virtual: vestavěný emulátor na virtuálních hodinách, tak rychle, jak počítač stačí (port se odmítne).</translation>
    </message>
    <message>
        <source>--clock takes real or virtual, not &quot;%1&quot;.</source>
        <translation>--clock přijímá real nebo virtual, ne &quot;%1&quot;.</translation>
    </message>
</context>
</TS>
