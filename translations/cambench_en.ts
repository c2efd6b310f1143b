<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>CamGenerator</name>
    <message>
        <source>The start position %1 is outside the range %2..%3. Enter a start inside the range.</source>
        <translation>The start position %1 is outside the range %2..%3. Enter a start inside the range.</translation>
    </message>
    <message>
        <source>The number of cams must be between 1 and %1.</source>
        <translation>The number of cams must be between 1 and %1.</translation>
    </message>
    <message>
        <source>The duty cycle must be above 0 % and below 100 %; at 100 % the cams would touch.</source>
        <translation>The duty cycle must be above 0 % and below 100 %; at 100 % the cams would touch.</translation>
    </message>
    <message>
        <source>%1 cams with %2 % duty do not fit into %3 positions. Choose fewer cams or another duty cycle.</source>
        <translation>%1 cams with %2 % duty do not fit into %3 positions. Choose fewer cams or another duty cycle.</translation>
    </message>
    <message>
        <source>The pitch (%1) must be larger than the cam length (%2), and the length at least 1; otherwise the cams overlap.</source>
        <translation>The pitch (%1) must be larger than the cam length (%2), and the length at least 1; otherwise the cams overlap.</translation>
    </message>
    <message>
        <source>These settings make more than %1 cams, the most a track holds. Choose a larger pitch.</source>
        <translation>These settings make more than %1 cams, the most a track holds. Choose a larger pitch.</translation>
    </message>
    <message>
        <source>No cam of length %1 fits between %2 and %3.</source>
        <translation>No cam of length %1 fits between %2 and %3.</translation>
    </message>
</context>
<context>
    <name>DeviceErrors</name>
    <message>
        <source>The device&apos;s RAM is too small for this setting (manual: &quot;RAM zu klein für Einstellung&quot;). Choose a smaller value, e.g. fewer PLC elements.</source>
        <translation>The device&apos;s RAM is too small for this setting (manual: &quot;RAM zu klein für Einstellung&quot;). Choose a smaller value, e.g. fewer PLC elements.</translation>
    </message>
    <message>
        <source>The dead-time compensation value is too large. Enter at most the device&apos;s maximum dead time (cambench-cli info: maxDeadTime).</source>
        <translation>The dead-time compensation value is too large. Enter at most the device&apos;s maximum dead time (cambench-cli info: maxDeadTime).</translation>
    </message>
    <message>
        <source>The device&apos;s EEPROM is defective. Back up what can still be read and have the device repaired.</source>
        <translation>The device&apos;s EEPROM is defective. Back up what can still be read and have the device repaired.</translation>
    </message>
    <message>
        <source>The device&apos;s EEPROM is full. Delete cams or programs that are no longer needed, then write again.</source>
        <translation>The device&apos;s EEPROM is full. Delete cams or programs that are no longer needed, then write again.</translation>
    </message>
    <message>
        <source>Checksum error in the device&apos;s EEPROM: the stored data may be damaged. Restore a backup or enter the data again.</source>
        <translation>Checksum error in the device&apos;s EEPROM: the stored data may be damaged. Restore a backup or enter the data again.</translation>
    </message>
    <message>
        <source>Block 0000 of the restore (!EE) has the wrong length: the image does not suit this device. Use an image taken from this kind of device.</source>
        <translation>Block 0000 of the restore (!EE) has the wrong length: the image does not suit this device. Use an image taken from this kind of device.</translation>
    </message>
    <message>
        <source>The device cannot erase its EEPROM. Switch it off and on and restore again; if that fails too, the device needs repair.</source>
        <translation>The device cannot erase its EEPROM. Switch it off and on and restore again; if that fails too, the device needs repair.</translation>
    </message>
    <message>
        <source>The restore (!EE) sent the blocks in the wrong block number order. Restore again from the start; if it happens again, the image file is damaged.</source>
        <translation>The restore (!EE) sent the blocks in the wrong block number order. Restore again from the start; if it happens again, the image file is damaged.</translation>
    </message>
    <message>
        <source>The CamCon cannot start after the restore (!EE): the data do not suit it. Restore the safety backup or an image taken from this device.</source>
        <translation>The CamCon cannot start after the restore (!EE): the data do not suit it. Restore the safety backup or an image taken from this device.</translation>
    </message>
    <message>
        <source>A block of the restore (!EE) has the wrong length: the image file is damaged. Restore another image.</source>
        <translation>A block of the restore (!EE) has the wrong length: the image file is damaged. Restore another image.</translation>
    </message>
    <message>
        <source>The device did not receive the data completely: the line lost bytes. Check the cable and the baud rate, then try again.</source>
        <translation>The device did not receive the data completely: the line lost bytes. Check the cable and the baud rate, then try again.</translation>
    </message>
    <message>
        <source>The manual gives no meaning for error -1 (it lists it only as &quot;unknown error&quot;). The device refused the request: check that the values lie within its limits and that the item exists.</source>
        <translation>The manual gives no meaning for error -1 (it lists it only as &quot;unknown error&quot;). The device refused the request: check that the values lie within its limits and that the item exists.</translation>
    </message>
    <message>
        <source>The manual gives no meaning for error %1. Note the number and the command and ask the device&apos;s supplier.</source>
        <translation>The manual gives no meaning for error %1. Note the number and the command and ask the device&apos;s supplier.</translation>
    </message>
</context>
<context>
    <name>PageWriteReport</name>
    <message numerus="yes">
        <source>%n edited value(s) on this page are not written. Replace them with what the device holds?</source>
        <translation>
            <numerusform>%n edited value on this page is not written. Replace it with what the device holds?</numerusform>
            <numerusform>%n edited values on this page are not written. Replace them with what the device holds?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ReplacementQuestion</name>
    <message>
        <source>not recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished">none</translation>
    </message>
    <message>
        <source>%1: %2 (the same)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: backup %2, this device %3  ← differs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device answering is not the one %1 was taken from.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 records no identity of the device it was taken from (an older backup): CamBench cannot tell whether the device answering is that device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1

Restore it here only if this device replaces the one the backup was taken from (or, for an older backup, is that device). Nothing has been written yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>It replaces that device: restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check which device answers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was written: which device answers could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Settings</name>
    <message>
        <source>Encoder</source>
        <translation>Encoder</translation>
    </message>
    <message>
        <source>The position encoder connected to the device, from the device&apos;s list of encoders, or the programmable special encoder set up on the special encoder page.</source>
        <translation>The position encoder connected to the device, from the device&apos;s list of encoders, or the programmable special encoder set up on the special encoder page.</translation>
    </message>
    <message>
        <source>SSI 256 Gray singleturn</source>
        <translation>SSI 256 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 360 Gray singleturn</source>
        <translation>SSI 360 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 512 Gray singleturn</source>
        <translation>SSI 512 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 1000 Gray singleturn</source>
        <translation>SSI 1000 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 1024 Gray singleturn</source>
        <translation>SSI 1024 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 2048 Gray singleturn</source>
        <translation>SSI 2048 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 4096 Gray singleturn</source>
        <translation>SSI 4096 Gray singleturn</translation>
    </message>
    <message>
        <source>SSI 8192 Gray singleturn</source>
        <translation>SSI 8192 Gray singleturn</translation>
    </message>
    <message>
        <source>Analogue SSI converter 8 bit (0..255)</source>
        <translation>Analogue SSI converter 8 bit (0..255)</translation>
    </message>
    <message>
        <source>Analogue SSI converter 12 bit (0..4095)</source>
        <translation>Analogue SSI converter 12 bit (0..4095)</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 1 turn</source>
        <translation>SSI multiturn 4096 x 1 turn</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 2 turns</source>
        <translation>SSI multiturn 4096 x 2 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 4 turns</source>
        <translation>SSI multiturn 4096 x 4 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 8 turns</source>
        <translation>SSI multiturn 4096 x 8 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 16 turns</source>
        <translation>SSI multiturn 4096 x 16 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 2 turns</source>
        <translation>SSI multiturn 8192 x 2 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 4 turns</source>
        <translation>SSI multiturn 8192 x 4 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 8 turns</source>
        <translation>SSI multiturn 8192 x 8 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 16 turns</source>
        <translation>SSI multiturn 8192 x 16 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 32 turns</source>
        <translation>SSI multiturn 8192 x 32 turns</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 64 turns</source>
        <translation>SSI multiturn 8192 x 64 turns</translation>
    </message>
    <message>
        <source>Programmable special encoder</source>
        <translation>Programmable special encoder</translation>
    </message>
    <message>
        <source>Encoder text line 1</source>
        <translation>Encoder text line 1</translation>
    </message>
    <message>
        <source>First text line describing the selected encoder, as the device shows it.</source>
        <translation>First text line describing the selected encoder, as the device shows it.</translation>
    </message>
    <message>
        <source>Encoder text line 2</source>
        <translation>Encoder text line 2</translation>
    </message>
    <message>
        <source>Second text line describing the selected encoder, as the device shows it.</source>
        <translation>Second text line describing the selected encoder, as the device shows it.</translation>
    </message>
    <message>
        <source>Actual value hysteresis</source>
        <translation>Actual value hysteresis</translation>
    </message>
    <message>
        <source>Change of the encoder value that is ignored, so that a shaft standing on an edge does not make the outputs flicker.</source>
        <translation>Change of the encoder value that is ignored, so that a shaft standing on an edge does not make the outputs flicker.</translation>
    </message>
    <message>
        <source>increments</source>
        <translation>increments</translation>
    </message>
    <message>
        <source>Maximum increments per cycle</source>
        <translation>Maximum increments per cycle</translation>
    </message>
    <message>
        <source>Largest plausible change of the encoder value within one cycle; a bigger jump is reported as an encoder error. 0 switches the check off.</source>
        <translation>Largest plausible change of the encoder value within one cycle; a bigger jump is reported as an encoder error. 0 switches the check off.</translation>
    </message>
    <message>
        <source>Gear multiplier</source>
        <translation>Gear multiplier</translation>
    </message>
    <message>
        <source>The encoder value is multiplied by this factor and divided by the gear divisor. A negative factor reverses the direction; 0 is not allowed.</source>
        <translation>The encoder value is multiplied by this factor and divided by the gear divisor. A negative factor reverses the direction; 0 is not allowed.</translation>
    </message>
    <message>
        <source>Gear divisor</source>
        <translation>Gear divisor</translation>
    </message>
    <message>
        <source>The encoder value multiplied by the gear multiplier is divided by this number.</source>
        <translation>The encoder value multiplied by the gear multiplier is divided by this number.</translation>
    </message>
    <message>
        <source>Actual value format</source>
        <translation>Actual value format</translation>
    </message>
    <message>
        <source>How the device displays the actual value (format text, e.g. the position of the decimal point and the unit).</source>
        <translation>How the device displays the actual value (format text, e.g. the position of the decimal point and the unit).</translation>
    </message>
    <message>
        <source>Special encoder type</source>
        <translation>Special encoder type</translation>
    </message>
    <message>
        <source>Which kind of programmable special encoder is set up (5 = timer). Chosen by writing one of the parameter pages.</source>
        <translation>Which kind of programmable special encoder is set up (5 = timer). Chosen by writing one of the parameter pages.</translation>
    </message>
    <message>
        <source>Special encoder text line 1</source>
        <translation>Special encoder text line 1</translation>
    </message>
    <message>
        <source>First text line the device shows for the special encoder.</source>
        <translation>First text line the device shows for the special encoder.</translation>
    </message>
    <message>
        <source>Special encoder text line 2</source>
        <translation>Special encoder text line 2</translation>
    </message>
    <message>
        <source>Second text line the device shows for the special encoder.</source>
        <translation>Second text line the device shows for the special encoder.</translation>
    </message>
    <message>
        <source>SSI resolution</source>
        <translation>SSI resolution</translation>
    </message>
    <message>
        <source>Number of data bits the SSI encoder sends per value.</source>
        <translation>Number of data bits the SSI encoder sends per value.</translation>
    </message>
    <message>
        <source>bits</source>
        <translation>bits</translation>
    </message>
    <message>
        <source>SSI first bit</source>
        <translation>SSI first bit</translation>
    </message>
    <message>
        <source>Position of the first valid bit in the SSI telegram.</source>
        <translation>Position of the first valid bit in the SSI telegram.</translation>
    </message>
    <message>
        <source>SSI capping</source>
        <translation>SSI capping</translation>
    </message>
    <message>
        <source>Number of low bits cut off the SSI value.</source>
        <translation>Number of low bits cut off the SSI value.</translation>
    </message>
    <message>
        <source>SSI error bit</source>
        <translation>SSI error bit</translation>
    </message>
    <message>
        <source>Bit of the SSI telegram that signals an encoder error (0 = none).</source>
        <translation>Bit of the SSI telegram that signals an encoder error (0 = none).</translation>
    </message>
    <message>
        <source>Parallel encoder resolution</source>
        <translation>Parallel encoder resolution</translation>
    </message>
    <message>
        <source>Increments per turn of the parallel encoder.</source>
        <translation>Increments per turn of the parallel encoder.</translation>
    </message>
    <message>
        <source>Parallel encoder first input</source>
        <translation>Parallel encoder first input</translation>
    </message>
    <message>
        <source>First of the inputs the parallel encoder is wired to.</source>
        <translation>First of the inputs the parallel encoder is wired to.</translation>
    </message>
    <message>
        <source>Parallel encoder code</source>
        <translation>Parallel encoder code</translation>
    </message>
    <message>
        <source>Whether the parallel encoder sends Gray code or binary.</source>
        <translation>Whether the parallel encoder sends Gray code or binary.</translation>
    </message>
    <message>
        <source>Gray code</source>
        <translation>Gray code</translation>
    </message>
    <message>
        <source>Binary</source>
        <translation>Binary</translation>
    </message>
    <message>
        <source>Incremental encoder resolution</source>
        <translation>Incremental encoder resolution</translation>
    </message>
    <message>
        <source>Increments per turn of the incremental encoder.</source>
        <translation>Increments per turn of the incremental encoder.</translation>
    </message>
    <message>
        <source>Incremental encoder divider</source>
        <translation>Incremental encoder divider</translation>
    </message>
    <message>
        <source>The incremental pulses are divided by this number.</source>
        <translation>The incremental pulses are divided by this number.</translation>
    </message>
    <message>
        <source>Incremental encoder clear mode</source>
        <translation>Incremental encoder clear mode</translation>
    </message>
    <message>
        <source>When the incremental counter is cleared (device-specific code).</source>
        <translation>When the incremental counter is cleared (device-specific code).</translation>
    </message>
    <message>
        <source>Multiturn resolution</source>
        <translation>Multiturn resolution</translation>
    </message>
    <message>
        <source>Increments per turn of the multiturn encoder.</source>
        <translation>Increments per turn of the multiturn encoder.</translation>
    </message>
    <message>
        <source>Multiturn turns</source>
        <translation>Multiturn turns</translation>
    </message>
    <message>
        <source>Number of turns the multiturn encoder counts.</source>
        <translation>Number of turns the multiturn encoder counts.</translation>
    </message>
    <message>
        <source>turns</source>
        <translation>turns</translation>
    </message>
    <message>
        <source>Multiturn divider</source>
        <translation>Multiturn divider</translation>
    </message>
    <message>
        <source>The multiturn value is divided by this number.</source>
        <translation>The multiturn value is divided by this number.</translation>
    </message>
    <message>
        <source>PLL pulses per input pulse</source>
        <translation>PLL pulses per input pulse</translation>
    </message>
    <message>
        <source>Increments the PLL generates for each input pulse.</source>
        <translation>Increments the PLL generates for each input pulse.</translation>
    </message>
    <message>
        <source>PLL pulses per turn</source>
        <translation>PLL pulses per turn</translation>
    </message>
    <message>
        <source>Input pulses per turn of the machine.</source>
        <translation>Input pulses per turn of the machine.</translation>
    </message>
    <message>
        <source>PLL error window</source>
        <translation>PLL error window</translation>
    </message>
    <message>
        <source>Deviation from the expected pulse count that is still accepted.</source>
        <translation>Deviation from the expected pulse count that is still accepted.</translation>
    </message>
    <message>
        <source>PLL pulse input</source>
        <translation>PLL pulse input</translation>
    </message>
    <message>
        <source>Input that receives the PLL&apos;s pulses.</source>
        <translation>Input that receives the PLL&apos;s pulses.</translation>
    </message>
    <message>
        <source>PLL clear input</source>
        <translation>PLL clear input</translation>
    </message>
    <message>
        <source>Input that clears the PLL&apos;s position (0 = none).</source>
        <translation>Input that clears the PLL&apos;s position (0 = none).</translation>
    </message>
    <message>
        <source>PLL sync output</source>
        <translation>PLL sync output</translation>
    </message>
    <message>
        <source>Output that signals that the PLL is synchronised (0 = none).</source>
        <translation>Output that signals that the PLL is synchronised (0 = none).</translation>
    </message>
    <message>
        <source>Timer step time</source>
        <translation>Timer step time</translation>
    </message>
    <message>
        <source>Time after which the timer encoder counts one step.</source>
        <translation>Time after which the timer encoder counts one step.</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Timer resolution</source>
        <translation>Timer resolution</translation>
    </message>
    <message>
        <source>Steps of the timer encoder before it starts again at zero.</source>
        <translation>Steps of the timer encoder before it starts again at zero.</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>steps</translation>
    </message>
    <message>
        <source>Timer hold input</source>
        <translation>Timer hold input</translation>
    </message>
    <message>
        <source>Input that holds the timer encoder (0 = none).</source>
        <translation>Input that holds the timer encoder (0 = none).</translation>
    </message>
    <message>
        <source>Timer clear input</source>
        <translation>Timer clear input</translation>
    </message>
    <message>
        <source>Input that sets the timer encoder back to zero (0 = none).</source>
        <translation>Input that sets the timer encoder back to zero (0 = none).</translation>
    </message>
    <message>
        <source>Axis type</source>
        <translation>Axis type</translation>
    </message>
    <message>
        <source>Rotary: the actual value runs round and cams may wrap through zero. Linear: the actual value runs from the start value upwards.</source>
        <translation>Rotary: the actual value runs round and cams may wrap through zero. Linear: the actual value runs from the start value upwards.</translation>
    </message>
    <message>
        <source>Rotary</source>
        <translation>Rotary</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Linear start value</source>
        <translation>Linear start value</translation>
    </message>
    <message>
        <source>Actual value at the start of a linear axis.</source>
        <translation>Actual value at the start of a linear axis.</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Zero-point shift added to the encoder value.</source>
        <translation>Zero-point shift added to the encoder value.</translation>
    </message>
    <message>
        <source>Preset value</source>
        <translation>Preset value</translation>
    </message>
    <message>
        <source>Actual value the device takes when the preset input switches on.</source>
        <translation>Actual value the device takes when the preset input switches on.</translation>
    </message>
    <message>
        <source>Preset input</source>
        <translation>Preset input</translation>
    </message>
    <message>
        <source>Input that sets the actual value to the preset value (0 = none).</source>
        <translation>Input that sets the actual value to the preset value (0 = none).</translation>
    </message>
    <message>
        <source>Preset retained at power-off</source>
        <translation>Preset retained at power-off</translation>
    </message>
    <message>
        <source>Whether a preset survives switching the device off and on (zero-voltage safe).</source>
        <translation>Whether a preset survives switching the device off and on (zero-voltage safe).</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Off</translation>
    </message>
    <message>
        <source>On</source>
        <translation>On</translation>
    </message>
    <message>
        <source>Speed factor</source>
        <translation>Speed factor</translation>
    </message>
    <message>
        <source>The measured speed is multiplied by this factor before it is displayed (0.00001 to 999.99999).</source>
        <translation>The measured speed is multiplied by this factor before it is displayed (0.00001 to 999.99999).</translation>
    </message>
    <message>
        <source>Speed format</source>
        <translation>Speed format</translation>
    </message>
    <message>
        <source>How the device displays the speed (format text).</source>
        <translation>How the device displays the speed (format text).</translation>
    </message>
    <message>
        <source>100% speed value</source>
        <translation>100% speed value</translation>
    </message>
    <message>
        <source>Speed value that counts as 100 %, e.g. for the analogue speed output.</source>
        <translation>Speed value that counts as 100 %, e.g. for the analogue speed output.</translation>
    </message>
    <message>
        <source>Speed accuracy</source>
        <translation>Speed accuracy</translation>
    </message>
    <message>
        <source>Resolution of the speed measurement (0.01 to 9.99).</source>
        <translation>Resolution of the speed measurement (0.01 to 9.99).</translation>
    </message>
    <message>
        <source>Display mode</source>
        <translation>Display mode</translation>
    </message>
    <message>
        <source>What the display shows: automatic change, speed or position. With speed or position an input can switch the display.</source>
        <translation>What the display shows: automatic change, speed or position. With speed or position an input can switch the display.</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatic</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Display switch input</source>
        <translation>Display switch input</translation>
    </message>
    <message>
        <source>Input that switches the display between speed and position (0 = none; only in display mode Speed or Position).</source>
        <translation>Input that switches the display between speed and position (0 = none; only in display mode Speed or Position).</translation>
    </message>
    <message>
        <source>Cable length</source>
        <translation>Cable length</translation>
    </message>
    <message>
        <source>Length of the encoder cable; the device compensates the signal delay.</source>
        <translation>Length of the encoder cable; the device compensates the signal delay.</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Minimum cycle time</source>
        <translation>Minimum cycle time</translation>
    </message>
    <message>
        <source>Shortest time of one device cycle, in 0.1 ms steps (0 to 10000 ms).</source>
        <translation>Shortest time of one device cycle, in 0.1 ms steps (0 to 10000 ms).</translation>
    </message>
    <message>
        <source>0.1 ms</source>
        <translation>0.1 ms</translation>
    </message>
    <message>
        <source>Current cycle time</source>
        <translation>Current cycle time</translation>
    </message>
    <message>
        <source>Time the device currently needs for one cycle, in 0.1 ms steps.</source>
        <translation>Time the device currently needs for one cycle, in 0.1 ms steps.</translation>
    </message>
    <message>
        <source>Safety output</source>
        <translation>Safety output</translation>
    </message>
    <message>
        <source>Output that is on while the device works without error (0 = none).</source>
        <translation>Output that is on while the device works without error (0 = none).</translation>
    </message>
    <message>
        <source>Actual value output</source>
        <translation>Actual value output</translation>
    </message>
    <message>
        <source>Whether and how the device passes its actual value on through outputs.</source>
        <translation>Whether and how the device passes its actual value on through outputs.</translation>
    </message>
    <message>
        <source>Do not send</source>
        <translation>Do not send</translation>
    </message>
    <message>
        <source>Send in Gray code</source>
        <translation>Send in Gray code</translation>
    </message>
    <message>
        <source>Send in binary</source>
        <translation>Send in binary</translation>
    </message>
    <message>
        <source>Send for DC115 master-slave</source>
        <translation>Send for DC115 master-slave</translation>
    </message>
    <message>
        <source>Direction output</source>
        <translation>Direction output</translation>
    </message>
    <message>
        <source>Output that shows the direction of rotation (0 = none).</source>
        <translation>Output that shows the direction of rotation (0 = none).</translation>
    </message>
    <message>
        <source>Standstill output</source>
        <translation>Standstill output</translation>
    </message>
    <message>
        <source>Output that switches when the axis stands still (0 = no standstill detection).</source>
        <translation>Output that switches when the axis stands still (0 = no standstill detection).</translation>
    </message>
    <message>
        <source>Standstill speed hysteresis</source>
        <translation>Standstill speed hysteresis</translation>
    </message>
    <message>
        <source>Speed below which the axis counts as standing still.</source>
        <translation>Speed below which the axis counts as standing still.</translation>
    </message>
    <message>
        <source>Analogue speed output</source>
        <translation>Analogue speed output</translation>
    </message>
    <message>
        <source>Whether the device puts out the speed as an analogue value.</source>
        <translation>Whether the device puts out the speed as an analogue value.</translation>
    </message>
    <message>
        <source>Analogue cam outputs</source>
        <translation>Analogue cam outputs</translation>
    </message>
    <message>
        <source>Number of analogue cam outputs in use.</source>
        <translation>Number of analogue cam outputs in use.</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Inputs</translation>
    </message>
    <message>
        <source>Number of inputs the device has (multiples of 8).</source>
        <translation>Number of inputs the device has (multiples of 8).</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>Number of outputs the device has (multiples of 8, 8 to 200).</source>
        <translation>Number of outputs the device has (multiples of 8, 8 to 200).</translation>
    </message>
    <message>
        <source>Dead-time outputs</source>
        <translation>Dead-time outputs</translation>
    </message>
    <message>
        <source>Number of outputs with dead-time compensation, counted from output 1 (multiples of 8).</source>
        <translation>Number of outputs with dead-time compensation, counted from output 1 (multiples of 8).</translation>
    </message>
    <message>
        <source>Keyboard lock input</source>
        <translation>Keyboard lock input</translation>
    </message>
    <message>
        <source>Input that locks the device&apos;s keyboard (0 = none).</source>
        <translation>Input that locks the device&apos;s keyboard (0 = none).</translation>
    </message>
    <message>
        <source>External program selection inputs</source>
        <translation>External program selection inputs</translation>
    </message>
    <message>
        <source>Number of inputs that select the program in binary (0 = no external program selection).</source>
        <translation>Number of inputs that select the program in binary (0 = no external program selection).</translation>
    </message>
    <message>
        <source>First program selection input</source>
        <translation>First program selection input</translation>
    </message>
    <message>
        <source>First of the inputs that select the program (0 = none).</source>
        <translation>First of the inputs that select the program (0 = none).</translation>
    </message>
    <message>
        <source>Program selection mode</source>
        <translation>Program selection mode</translation>
    </message>
    <message>
        <source>When a newly selected program takes effect: slowly, within one cycle, or when the axis passes the program selection actual value.</source>
        <translation>When a newly selected program takes effect: slowly, within one cycle, or when the axis passes the program selection actual value.</translation>
    </message>
    <message>
        <source>Slow</source>
        <translation>Slow</translation>
    </message>
    <message>
        <source>Within one cycle</source>
        <translation>Within one cycle</translation>
    </message>
    <message>
        <source>At actual value</source>
        <translation>At actual value</translation>
    </message>
    <message>
        <source>Program selection actual value</source>
        <translation>Program selection actual value</translation>
    </message>
    <message>
        <source>Actual value at which a new program takes effect (mode &quot;At actual value&quot; only).</source>
        <translation>Actual value at which a new program takes effect (mode &quot;At actual value&quot; only).</translation>
    </message>
    <message>
        <source>Communication protocol</source>
        <translation>Communication protocol</translation>
    </message>
    <message>
        <source>Protocol of the serial interface. Changing it ends the connection with the current protocol.</source>
        <translation>Protocol of the serial interface. Changing it ends the connection with the current protocol.</translation>
    </message>
    <message>
        <source>Cam-BUS</source>
        <translation>Cam-BUS</translation>
    </message>
    <message>
        <source>Standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Multiuser</source>
        <translation>Multiuser</translation>
    </message>
    <message>
        <source>S5-L1</source>
        <translation>S5-L1</translation>
    </message>
    <message>
        <source>3964R</source>
        <translation>3964R</translation>
    </message>
    <message>
        <source>Device number</source>
        <translation>Device number</translation>
    </message>
    <message>
        <source>Number of the device on a Multiuser or Cam-BUS line.</source>
        <translation>Number of the device on a Multiuser or Cam-BUS line.</translation>
    </message>
    <message>
        <source>Analogue outputs</source>
        <translation>Analogue outputs</translation>
    </message>
    <message>
        <source>How many internal analogue outputs are in use.</source>
        <translation>How many internal analogue outputs are in use.</translation>
    </message>
    <message>
        <source>No analogue value</source>
        <translation>No analogue value</translation>
    </message>
    <message>
        <source>1 internal analogue output</source>
        <translation>1 internal analogue output</translation>
    </message>
    <message>
        <source>2 internal analogue outputs</source>
        <translation>2 internal analogue outputs</translation>
    </message>
    <message>
        <source>Analogue 1 offset</source>
        <translation>Analogue 1 offset</translation>
    </message>
    <message>
        <source>Offset adjustment of analogue value 1.</source>
        <translation>Offset adjustment of analogue value 1.</translation>
    </message>
    <message>
        <source>Analogue 2 offset</source>
        <translation>Analogue 2 offset</translation>
    </message>
    <message>
        <source>Offset adjustment of analogue value 2.</source>
        <translation>Offset adjustment of analogue value 2.</translation>
    </message>
    <message>
        <source>Analogue 1 factor</source>
        <translation>Analogue 1 factor</translation>
    </message>
    <message>
        <source>Gain adjustment of analogue value 1.</source>
        <translation>Gain adjustment of analogue value 1.</translation>
    </message>
    <message>
        <source>Analogue 2 factor</source>
        <translation>Analogue 2 factor</translation>
    </message>
    <message>
        <source>Gain adjustment of analogue value 2.</source>
        <translation>Gain adjustment of analogue value 2.</translation>
    </message>
    <message>
        <source>Terminal mode</source>
        <translation>Terminal mode</translation>
    </message>
    <message>
        <source>Normal operation or terminal operation of the device.</source>
        <translation>Normal operation or terminal operation of the device.</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation>Terminal</translation>
    </message>
    <message>
        <source>Device language</source>
        <translation>Device language</translation>
    </message>
    <message>
        <source>Language of the device&apos;s display: 0 German, 1 English, 2 French; further numbers depend on the firmware.</source>
        <translation>Language of the device&apos;s display: 0 German, 1 English, 2 French; further numbers depend on the firmware.</translation>
    </message>
    <message>
        <source>PLC accelerator</source>
        <translation>PLC accelerator</translation>
    </message>
    <message>
        <source>Whether the PLC accelerator hardware is fitted.</source>
        <translation>Whether the PLC accelerator hardware is fitted.</translation>
    </message>
    <message>
        <source>Not fitted</source>
        <translation>Not fitted</translation>
    </message>
    <message>
        <source>Fitted</source>
        <translation>Fitted</translation>
    </message>
    <message>
        <source>PLC module</source>
        <translation>PLC module</translation>
    </message>
    <message>
        <source>Switches the PLC module off or on; &quot;flags retained&quot; keeps the flags at power-off.</source>
        <translation>Switches the PLC module off or on; &quot;flags retained&quot; keeps the flags at power-off.</translation>
    </message>
    <message>
        <source>On, flags retained</source>
        <translation>On, flags retained</translation>
    </message>
    <message>
        <source>PLC inputs</source>
        <translation>PLC inputs</translation>
    </message>
    <message>
        <source>Number of PLC inputs (multiples of 8).</source>
        <translation>Number of PLC inputs (multiples of 8).</translation>
    </message>
    <message>
        <source>PLC outputs</source>
        <translation>PLC outputs</translation>
    </message>
    <message>
        <source>Number of PLC outputs (multiples of 8).</source>
        <translation>Number of PLC outputs (multiples of 8).</translation>
    </message>
    <message>
        <source>PLC flags</source>
        <translation>PLC flags</translation>
    </message>
    <message>
        <source>Number of PLC flags (M, multiples of 8).</source>
        <translation>Number of PLC flags (M, multiples of 8).</translation>
    </message>
    <message>
        <source>PLC X flags</source>
        <translation>PLC X flags</translation>
    </message>
    <message>
        <source>Number of PLC X flags (multiples of 8).</source>
        <translation>Number of PLC X flags (multiples of 8).</translation>
    </message>
    <message>
        <source>PLC timers and counters</source>
        <translation>PLC timers and counters</translation>
    </message>
    <message>
        <source>Number of PLC timers and counters (multiples of 8).</source>
        <translation>Number of PLC timers and counters (multiples of 8).</translation>
    </message>
    <message>
        <source>PLC V inputs</source>
        <translation>PLC V inputs</translation>
    </message>
    <message>
        <source>Number of PLC V inputs (multiples of 8).</source>
        <translation>Number of PLC V inputs (multiples of 8).</translation>
    </message>
    <message>
        <source>PLC S inputs</source>
        <translation>PLC S inputs</translation>
    </message>
    <message>
        <source>Number of PLC S inputs (multiples of 8).</source>
        <translation>Number of PLC S inputs (multiples of 8).</translation>
    </message>
</context>
<context>
    <name>TimingText</name>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished">%1 %2</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished">%1 ms</translation>
    </message>
    <message>
        <source>above %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at every speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: cam %2 vanishes %3 (the switch-off dead time is longer than the switch-on one).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: cams %2 and %3 merge %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: cam %2 is on for less than the minimum pulse %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the switch points move by more than one cycle %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench</name>
    <message>
        <source>On the device: %1</source>
        <translation type="unfinished">On the device: %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished">%1 ms</translation>
    </message>
    <message>
        <source>%1: &quot;volatile&quot; holds an empty item; name items as a comparison names them (&quot;V12&quot;) or a range (&quot;V100-V199&quot;).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the volatile range &quot;%2&quot; ends below its start; write it low to high.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::AccessGridModel</name>
    <message>
        <source>Output %1: allowed (the user may change all outputs)</source>
        <translation>Output %1: allowed (the user may change all outputs)</translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation>Output %1</translation>
    </message>
</context>
<context>
    <name>cambench::AnalogueCamsPage</name>
    <message>
        <source>Analogue cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished">Position</translation>
    </message>
    <message>
        <source>Analogue value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Between two base points the analogue output follows a straight line (with interpolation on). Positions must rise from point to point.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read analogue cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading analogue cams failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue cams of output %1 read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no such point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
    <message>
        <source>Analogue output %1: not read from the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1: edited, not written. On the device: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1: as on the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this device has no analogue outputs, so it has no analogue cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this device has analogue outputs 1..%1 only</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::BackupPage</name>
    <message>
        <source>Backup or restore…</source>
        <translation>Backup or restore…</translation>
    </message>
    <message>
        <source>Backup</source>
        <translation>Backup</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Backup and restore&lt;/h3&gt;&lt;p&gt;A &lt;b&gt;backup&lt;/b&gt; copies the whole EEPROM of the device (cam programs, dead times, settings, users, PLC) block by block into a file.&lt;/p&gt;&lt;p&gt;A &lt;b&gt;restore&lt;/b&gt; erases the device and writes such a file back. CamBench checks the file first, restores it only to the device it was taken from (or to its replacement when you say so), and saves what the device holds now into a safety backup before it erases anything.&lt;/p&gt;&lt;p&gt;If a restore is interrupted, the device stays erased and does not run until an image is restored completely: keep the safety backup.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::BackupProgramsView</name>
    <message>
        <source>Hide outputs without a difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1</source>
        <translation type="unfinished">Program %1</translation>
    </message>
    <message>
        <source>Program %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n difference</numerusform>
            <numerusform>%n differences</numerusform>
        </translation>
    </message>
    <message>
        <source>Programs that differ:</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>A: %1, program %2. B: %3, program %2. %n difference(s) of cams.</source>
        <translation>
            <numerusform>A: %1, program %2. B: %3, program %2. %n difference of cams.</numerusform>
            <numerusform>A: %1, program %2. B: %3, program %2. %n differences of cams.</numerusform>
        </translation>
    </message>
    <message>
        <source>Name &quot;%1&quot; → &quot;%2&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::BackupWizard</name>
    <message>
        <source>EPROM %1, device number %2, %3 outputs, %4 programs, positions %5 … %6</source>
        <translation>EPROM %1, device number %2, %3 outputs, %4 programs, positions %5 … %6</translation>
    </message>
    <message>
        <source>Backup and restore</source>
        <translation>Backup and restore</translation>
    </message>
    <message>
        <source>Backup or restore</source>
        <translation>Backup or restore</translation>
    </message>
    <message>
        <source>Back up the device into a file</source>
        <translation>Back up the device into a file</translation>
    </message>
    <message>
        <source>Restore the device from a file</source>
        <translation>Restore the device from a file</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Browse…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>File:</translation>
    </message>
    <message>
        <source>EEPROM images (*.json)</source>
        <translation>EEPROM images (*.json)</translation>
    </message>
    <message>
        <source>Backup file</source>
        <translation>Backup file</translation>
    </message>
    <message>
        <source>Image to restore</source>
        <translation>Image to restore</translation>
    </message>
    <message>
        <source>Check the image</source>
        <translation>Check the image</translation>
    </message>
    <message>
        <source>The restore erases the device. Before that, CamBench saves what the device holds now into a safety backup.</source>
        <translation>The restore erases the device. Before that, CamBench saves what the device holds now into a safety backup.</translation>
    </message>
    <message>
        <source>Safety backup:</source>
        <translation>Safety backup:</translation>
    </message>
    <message>
        <source>Choose a file first.</source>
        <translation>Choose a file first.</translation>
    </message>
    <message>
        <source>Connect to the device first.</source>
        <translation>Connect to the device first.</translation>
    </message>
    <message>
        <source>This file cannot be restored: %1</source>
        <translation>This file cannot be restored: %1</translation>
    </message>
    <message>
        <source>Choose where the safety backup goes.</source>
        <translation>Choose where the safety backup goes.</translation>
    </message>
    <message numerus="yes">
        <source>Image: %1
Taken %2 with %3, %n block(s), %4 bytes.</source>
        <translation>
            <numerusform>Image: %1
Taken %2 with %3, %n block, %4 bytes.</numerusform>
            <numerusform>Image: %1
Taken %2 with %3, %n blocks, %4 bytes.</numerusform>
        </translation>
    </message>
    <message>
        <source>Device: %1</source>
        <translation>Device: %1</translation>
    </message>
    <message>
        <source>The image matches this device.</source>
        <translation>The image matches this device.</translation>
    </message>
    <message>
        <source>The image does NOT match this device:</source>
        <translation>The image does NOT match this device:</translation>
    </message>
    <message>
        <source>Reading the EEPROM of the device into %1…</source>
        <translation>Reading the EEPROM of the device into %1…</translation>
    </message>
    <message>
        <source>Backup</source>
        <translation>Backup</translation>
    </message>
    <message>
        <source>Backup failed, no file was written: %1</source>
        <translation>Backup failed, no file was written: %1</translation>
    </message>
    <message numerus="yes">
        <source>Backup complete: %n block(s), %1 bytes written to %2. Nothing failed.</source>
        <translation>
            <numerusform>Backup complete: %n block, %1 bytes written to %2. Nothing failed.</numerusform>
            <numerusform>Backup complete: %n blocks, %1 bytes written to %2. Nothing failed.</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Restore</translation>
    </message>
    <message numerus="yes">
        <source>Restore complete: %n block(s) written, 0 failed. The safety backup of the previous content is %1.</source>
        <translation>
            <numerusform>Restore complete: %n block written, 0 failed. The safety backup of the previous content is %1.</numerusform>
            <numerusform>Restore complete: %n blocks written, 0 failed. The safety backup of the previous content is %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel the restore? If the device is already being written, it stays ERASED until you restore an image.</source>
        <translation>Cancel the restore? If the device is already being written, it stays ERASED until you restore an image.</translation>
    </message>
    <message>
        <source>Cancel the backup? No file will be written.</source>
        <translation>Cancel the backup? No file will be written.</translation>
    </message>
    <message>
        <source>This erases the device (%1) and writes the image %2 into it. Outputs may switch while the device restarts.

Erase and restore now?</source>
        <translation>This erases the device (%1) and writes the image %2 into it. Outputs may switch while the device restarts.

Erase and restore now?</translation>
    </message>
    <message>
        <source>Erase and restore</source>
        <translation>Erase and restore</translation>
    </message>
    <message numerus="yes">
        <source>Step 1 of 2: saving what the device holds now into %1; step 2: erasing the device and writing %n block(s).</source>
        <translation>
            <numerusform>Step 1 of 2: saving what the device holds now into %1; step 2: erasing the device and writing %n block.</numerusform>
            <numerusform>Step 1 of 2: saving what the device holds now into %1; step 2: erasing the device and writing %n blocks.</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore NOT done, the device is unchanged: %1</source>
        <translation>Restore NOT done, the device is unchanged: %1</translation>
    </message>
    <message>
        <source>Restore FAILED: %1</source>
        <translation>Restore FAILED: %1</translation>
    </message>
    <message>
        <source>A backup copies the device&apos;s whole EEPROM into a file. A restore erases the device and writes such a file back. The file holds the users&apos; access codes: keep it where only you can read it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CamBusView</name>
    <message>
        <source>&lt;b&gt;Cam-BUS&lt;/b&gt; as this PC hears it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not on a Cam-BUS: connect with the Cam-BUS protocol to see its users and the token.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not live: nothing heard from the line for %1 s; the users below are the last ones heard.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Initialisation phase: the master searches the users (%n found so far).</source>
        <translation>
            <numerusform>Initialisation phase: the master searches the users (%n found so far).</numerusform>
            <numerusform>Initialisation phase: the master searches the users (%n found so far).</numerusform>
        </translation>
    </message>
    <message>
        <source>Listening: no token heard yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n users · master %1 · token with %2 · %3 rounds/s</source>
        <translation>
            <numerusform>%n user · master %1 · token with %2 · %3 rounds/s</numerusform>
            <numerusform>%n users · master %1 · token with %2 · %3 rounds/s</numerusform>
        </translation>
    </message>
    <message>
        <source>Initialisation phases heard since connecting: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>master: passes the token</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this PC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>does not answer (stays in the table until the next initialisation phase)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CamConGui</name>
    <message>
        <source>CamCon %1, device number %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon %1 (device %2)</source>
        <translation type="unfinished">CamCon %1 (device %2)</translation>
    </message>
    <message>
        <source>offline project</source>
        <translation type="unfinished">offline project</translation>
    </message>
</context>
<context>
    <name>cambench::CamConIdentityPanel</name>
    <message>
        <source>Not read from a device (offline project).</source>
        <translation type="unfinished">Not read from a device (offline project).</translation>
    </message>
    <message>
        <source>Last connected: CamCon %1, device number %2, at %3. Not necessarily the device on the port chosen now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 … %2</source>
        <translation type="unfinished">%1 … %2</translation>
    </message>
    <message>
        <source>Firmware (EPROM date):</source>
        <translation type="unfinished">Firmware (EPROM date):</translation>
    </message>
    <message>
        <source>Device number:</source>
        <translation type="unfinished">Device number:</translation>
    </message>
    <message>
        <source>Outputs:</source>
        <translation type="unfinished">Outputs:</translation>
    </message>
    <message>
        <source>Inputs:</source>
        <translation type="unfinished">Inputs:</translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation type="unfinished">Programs:</translation>
    </message>
    <message>
        <source>0 … %1</source>
        <translation type="unfinished">0 … %1</translation>
    </message>
    <message>
        <source>Position range:</source>
        <translation type="unfinished">Position range:</translation>
    </message>
    <message>
        <source>Outputs with dead time:</source>
        <translation type="unfinished">Outputs with dead time:</translation>
    </message>
    <message>
        <source>Maximum dead time:</source>
        <translation type="unfinished">Maximum dead time:</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished">%1 ms</translation>
    </message>
    <message>
        <source>Programmed cams:</source>
        <translation type="unfinished">Programmed cams:</translation>
    </message>
    <message>
        <source>Free cam memory:</source>
        <translation type="unfinished">Free cam memory:</translation>
    </message>
    <message numerus="yes">
        <source>%n cam(s)</source>
        <translation>
            <numerusform>%n cam</numerusform>
            <numerusform>%n cams</numerusform>
        </translation>
    </message>
    <message>
        <source>CPU clock:</source>
        <translation type="unfinished">CPU clock:</translation>
    </message>
    <message>
        <source>25.2 MHz</source>
        <translation type="unfinished">25.2 MHz</translation>
    </message>
    <message>
        <source>16.7 MHz</source>
        <translation type="unfinished">16.7 MHz</translation>
    </message>
    <message>
        <source>Temperature:</source>
        <translation type="unfinished">Temperature:</translation>
    </message>
    <message>
        <source>no sensor</source>
        <translation type="unfinished">no sensor</translation>
    </message>
    <message>
        <source>%1 °C</source>
        <translation type="unfinished">%1 °C</translation>
    </message>
</context>
<context>
    <name>cambench::CamConSectionPage</name>
    <message>
        <source>%1: nothing to write, the device holds what you see.</source>
        <translation type="unfinished">%1: nothing to write, the device holds what you see.</translation>
    </message>
    <message>
        <source>%1: writing…</source>
        <translation type="unfinished">%1: writing…</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n other item(s) of this section were already as on the device and not sent.</source>
        <translation>
            <numerusform>%n other item of this section was already as on the device and not sent.</numerusform>
            <numerusform>%n other items of this section were already as on the device and not sent.</numerusform>
        </translation>
    </message>
    <message>
        <source>Read from device</source>
        <translation type="unfinished">Read from device</translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation type="unfinished">Write changes</translation>
    </message>
</context>
<context>
    <name>cambench::CamConWindow</name>
    <message>
        <source>&amp;Read everything</source>
        <translation type="unfinished">&amp;Read everything</translation>
    </message>
    <message>
        <source>Co&amp;mpare with device…</source>
        <translation type="unfinished">Co&amp;mpare with device…</translation>
    </message>
    <message>
        <source>&amp;Backup and restore…</source>
        <translation type="unfinished">&amp;Backup and restore…</translation>
    </message>
    <message>
        <source>Back up all devices on this &amp;line…</source>
        <translation type="unfinished">Back up all devices on this &amp;line…</translation>
    </message>
    <message>
        <source>The device did not identify itself: %1 Your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the device…</source>
        <translation type="unfinished">Reading the device…</translation>
    </message>
    <message>
        <source>Reading the device: %1</source>
        <translation type="unfinished">Reading the device: %1</translation>
    </message>
    <message>
        <source>Reading everything the device holds…</source>
        <translation type="unfinished">Reading everything the device holds…</translation>
    </message>
    <message>
        <source>Everything read from the device.</source>
        <translation type="unfinished">Everything read from the device.</translation>
    </message>
    <message>
        <source>Read from the device, except: %1</source>
        <translation type="unfinished">Read from the device, except: %1</translation>
    </message>
    <message>
        <source>Reading the device failed: %1 Your edits are kept.</source>
        <translation type="unfinished">Reading the device failed: %1 Your edits are kept.</translation>
    </message>
    <message>
        <source>Write: %1</source>
        <translation type="unfinished">Write: %1</translation>
    </message>
    <message>
        <source>Unwritten changes</source>
        <translation type="unfinished">Unwritten changes</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) are not written to the device. Close anyway?</source>
        <translation>
            <numerusform>%n change is not written to the device. Close anyway?</numerusform>
            <numerusform>%n changes are not written to the device. Close anyway?</numerusform>
        </translation>
    </message>
    <message>
        <source>Compare with device…</source>
        <translation type="unfinished">Compare with device…</translation>
    </message>
    <message>
        <source>Save project…</source>
        <translation type="unfinished">Save project…</translation>
    </message>
    <message>
        <source>Close without writing</source>
        <translation type="unfinished">Close without writing</translation>
    </message>
    <message>
        <source>&amp;New project…</source>
        <translation type="unfinished">&amp;New project…</translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation type="unfinished">&amp;Open project…</translation>
    </message>
    <message>
        <source>Recent &amp;files</source>
        <translation type="unfinished">Recent &amp;files</translation>
    </message>
    <message>
        <source>&amp;Save project</source>
        <translation type="unfinished">&amp;Save project</translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation type="unfinished">Save project &amp;as…</translation>
    </message>
    <message>
        <source>Commissioning &amp;report (PDF)…</source>
        <translation type="unfinished">Commissioning &amp;report (PDF)…</translation>
    </message>
    <message>
        <source>New project</source>
        <translation type="unfinished">New project</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) are not written or saved. Discard them for a new, empty project?</source>
        <translation>
            <numerusform>%n change is not written or saved. Discard it for a new, empty project?</numerusform>
            <numerusform>%n changes are not written or saved. Discard them for a new, empty project?</numerusform>
        </translation>
    </message>
    <message>
        <source>Open project</source>
        <translation type="unfinished">Open project</translation>
    </message>
    <message>
        <source>CamBench projects (*.json)</source>
        <translation type="unfinished">CamBench projects (*.json)</translation>
    </message>
    <message>
        <source>The project %1 was not opened.</source>
        <translation type="unfinished">The project %1 was not opened.</translation>
    </message>
    <message>
        <source>Project %1 not opened: your edits are unchanged.</source>
        <translation type="unfinished">Project %1 not opened: your edits are unchanged.</translation>
    </message>
    <message>
        <source>Project %1 opened. Its content is not on the device until you write it.</source>
        <translation type="unfinished">Project %1 opened. Its content is not on the device until you write it.</translation>
    </message>
    <message>
        <source>No recent projects</source>
        <translation type="unfinished">No recent projects</translation>
    </message>
    <message>
        <source>&amp;Clear list</source>
        <translation type="unfinished">&amp;Clear list</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation type="unfinished">Save project</translation>
    </message>
    <message>
        <source>The device is still being read; the project was not saved. Save again when the reading is done.</source>
        <translation type="unfinished">The device is still being read; the project was not saved. Save again when the reading is done.</translation>
    </message>
    <message>
        <source>The project was not saved.</source>
        <translation type="unfinished">The project was not saved.</translation>
    </message>
    <message>
        <source>Project saved to %1.</source>
        <translation type="unfinished">Project saved to %1.</translation>
    </message>
    <message numerus="yes">
        <source>Project saved to %1. %n value(s) are outside what a write accepts (%2).</source>
        <translation>
            <numerusform>Project saved to %1. %n value is outside what a write accepts (%2).</numerusform>
            <numerusform>Project saved to %1. %n values are outside what a write accepts (%2).</numerusform>
        </translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation type="unfinished">Commissioning report</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished">PDF files (*.pdf)</translation>
    </message>
    <message>
        <source>Report written to %1.</source>
        <translation type="unfinished">Report written to %1.</translation>
    </message>
    <message>
        <source>Compare &amp;programs…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timing tables at the speed (%1); 0 leaves them out:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The start pages are read from it; the rest says &quot;not read&quot; until Read everything or Compare.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CamDiagramWidget</name>
    <message>
        <source>Output %1, cam %2: on %3, off %4, length %5</source>
        <translation>Output %1, cam %2: on %3, off %4, length %5</translation>
    </message>
    <message>
        <source>Changed, not yet written to the device.</source>
        <translation>Changed, not yet written to the device.</translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <source>Output %1, cam %2 at %3: never switches on (it vanishes).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1, cam %2 at %3: switches on at %4, off at %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On for %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programmed: on %1, off %2; dead time %3 on, %4 off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At %1 output %2 switches as drawn. First limit: %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CamDocument</name>
    <message>
        <source>Change cam on output %1</source>
        <translation>Change cam on output %1</translation>
    </message>
    <message>
        <source>Add cam to output %1</source>
        <translation>Add cam to output %1</translation>
    </message>
    <message>
        <source>Delete cam of output %1</source>
        <translation>Delete cam of output %1</translation>
    </message>
    <message>
        <source>Copy output %1 to output %2 of program %3</source>
        <translation>Copy output %1 to output %2 of program %3</translation>
    </message>
    <message>
        <source>Copy program %1 to program %2</source>
        <translation>Copy program %1 to program %2</translation>
    </message>
    <message>
        <source>Generate cams on output %1</source>
        <translation>Generate cams on output %1</translation>
    </message>
    <message>
        <source>Rename program %1</source>
        <translation>Rename program %1</translation>
    </message>
    <message>
        <source>Rename output %1</source>
        <translation>Rename output %1</translation>
    </message>
    <message>
        <source>Change dead time of output %1</source>
        <translation>Change dead time of output %1</translation>
    </message>
    <message>
        <source>Take program %1 from the device</source>
        <translation>Take program %1 from the device</translation>
    </message>
    <message>
        <source>Take program %1 from the file</source>
        <translation>Take program %1 from the file</translation>
    </message>
    <message>
        <source>Take names and dead times</source>
        <translation>Take names and dead times</translation>
    </message>
</context>
<context>
    <name>cambench::CamEditorWidget</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Undo</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Redo</translation>
    </message>
    <message>
        <source>&amp;Read Program</source>
        <translation>&amp;Read Program</translation>
    </message>
    <message>
        <source>Read the current program from the device</source>
        <translation>Read the current program from the device</translation>
    </message>
    <message>
        <source>&amp;Write Program</source>
        <translation>&amp;Write Program</translation>
    </message>
    <message>
        <source>Write the current program to the device</source>
        <translation>Write the current program to the device</translation>
    </message>
    <message>
        <source>&amp;Add Cam</source>
        <translation>&amp;Add Cam</translation>
    </message>
    <message>
        <source>Add a cam to the selected output</source>
        <translation>Add a cam to the selected output</translation>
    </message>
    <message>
        <source>&amp;Delete Cam</source>
        <translation>&amp;Delete Cam</translation>
    </message>
    <message>
        <source>Delete the selected cam</source>
        <translation>Delete the selected cam</translation>
    </message>
    <message>
        <source>Copy &amp;Output To…</source>
        <translation>Copy &amp;Output To…</translation>
    </message>
    <message>
        <source>Copy the cams of the selected output to another output</source>
        <translation>Copy the cams of the selected output to another output</translation>
    </message>
    <message>
        <source>Copy &amp;Program To…</source>
        <translation>Copy &amp;Program To…</translation>
    </message>
    <message>
        <source>Copy the whole program to another program number</source>
        <translation>Copy the whole program to another program number</translation>
    </message>
    <message>
        <source>&amp;Generate Cams…</source>
        <translation>&amp;Generate Cams…</translation>
    </message>
    <message>
        <source>Replace the cams of the selected output by evenly spaced cams</source>
        <translation>Replace the cams of the selected output by evenly spaced cams</translation>
    </message>
    <message>
        <source>&amp;Import CSV…</source>
        <translation>&amp;Import CSV…</translation>
    </message>
    <message>
        <source>Replace the cams of this program from a CSV file</source>
        <translation>Replace the cams of this program from a CSV file</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>&amp;Export CSV…</translation>
    </message>
    <message>
        <source>Save the cams of this program as a CSV file</source>
        <translation>Save the cams of this program as a CSV file</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;In</translation>
    </message>
    <message>
        <source>Show a smaller part of the axis</source>
        <translation>Show a smaller part of the axis</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Zoom &amp;Out</translation>
    </message>
    <message>
        <source>Show a larger part of the axis</source>
        <translation>Show a larger part of the axis</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>&amp;Fit</translation>
    </message>
    <message>
        <source>Show the whole axis IMIN..IMAX</source>
        <translation>Show the whole axis IMIN..IMAX</translation>
    </message>
    <message>
        <source>no name</source>
        <translation>no name</translation>
    </message>
    <message>
        <source>&amp;Program:</source>
        <translation>&amp;Program:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>Cams of output %1</source>
        <translation>Cams of output %1</translation>
    </message>
    <message>
        <source>Cams of output %1 (%2)</source>
        <translation>Cams of output %1 (%2)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Program Name</source>
        <translation>Program Name</translation>
    </message>
    <message>
        <source>Copy Output</source>
        <translation>Copy Output</translation>
    </message>
    <message>
        <source>Copy the cams of output %1 to output (its cams are replaced):</source>
        <translation>Copy the cams of output %1 to output (its cams are replaced):</translation>
    </message>
    <message>
        <source>Copy Program</source>
        <translation>Copy Program</translation>
    </message>
    <message>
        <source>Copy program %1 to program (its cams and name are replaced):</source>
        <translation>Copy program %1 to program (its cams and name are replaced):</translation>
    </message>
    <message>
        <source>%1: output %2 does not exist; the device has outputs 1..%3. Nothing was imported.</source>
        <translation>%1: output %2 does not exist; the device has outputs 1..%3. Nothing was imported.</translation>
    </message>
    <message>
        <source>Import cams from %1</source>
        <translation>Import cams from %1</translation>
    </message>
    <message>
        <source>Import Cams</source>
        <translation>Import Cams</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV files (*.csv);;All files (*)</translation>
    </message>
    <message numerus="yes">
        <source>The cams were imported, but %n need fixing before they can be written (shown in red):
%1</source>
        <translation>
            <numerusform>The cams were imported, but %n needs fixing before they can be written (shown in red):
%1</numerusform>
            <numerusform>The cams were imported, but %n need fixing before they can be written (shown in red):
%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Cams</source>
        <translation>Export Cams</translation>
    </message>
    <message>
        <source>program-%1.csv</source>
        <translation>program-%1.csv</translation>
    </message>
    <message>
        <source>Diagram</source>
        <translation>Diagram</translation>
    </message>
    <message>
        <source>%1 (not read)</source>
        <translation>%1 (not read)</translation>
    </message>
</context>
<context>
    <name>cambench::CamGeneratorDialog</name>
    <message>
        <source>Fixed &amp;length and pitch</source>
        <translation>Fixed &amp;length and pitch</translation>
    </message>
    <message>
        <source>&amp;Number of cams and duty cycle</source>
        <translation>&amp;Number of cams and duty cycle</translation>
    </message>
    <message>
        <source>Generate Cams for Output %1</source>
        <translation>Generate Cams for Output %1</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>&amp;Start position:</source>
        <translation>&amp;Start position:</translation>
    </message>
    <message>
        <source>Cam l&amp;ength:</source>
        <translation>Cam l&amp;ength:</translation>
    </message>
    <message>
        <source>&amp;Pitch:</source>
        <translation>&amp;Pitch:</translation>
    </message>
    <message>
        <source>&amp;Count:</source>
        <translation>&amp;Count:</translation>
    </message>
    <message>
        <source>&amp;Duty cycle:</source>
        <translation>&amp;Duty cycle:</translation>
    </message>
    <message>
        <source>The cams replace all cams of output %1.</source>
        <translation>The cams replace all cams of output %1.</translation>
    </message>
    <message>
        <source>%1–%2</source>
        <translation>%1–%2</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message numerus="yes">
        <source>%n cam(s): %1</source>
        <translation>
            <numerusform>%n cam: %1</numerusform>
            <numerusform>%n cams: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
</context>
<context>
    <name>cambench::CamPage</name>
    <message>
        <source>Read program %1</source>
        <translation>Read program %1</translation>
    </message>
    <message>
        <source>Write program %1</source>
        <translation>Write program %1</translation>
    </message>
    <message>
        <source>Reading program %1…</source>
        <translation>Reading program %1…</translation>
    </message>
    <message>
        <source>Program %1 not read: %2 Your edits are kept.</source>
        <translation>Program %1 not read: %2 Your edits are kept.</translation>
    </message>
    <message>
        <source>Program %1 read.</source>
        <translation>Program %1 read.</translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation>Program %1: %2</translation>
    </message>
    <message>
        <source>Program %1, output %2</source>
        <translation>Program %1, output %2</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>Program %1 name</source>
        <translation>Program %1 name</translation>
    </message>
    <message>
        <source>Cam programs</source>
        <translation>Cam programs</translation>
    </message>
    <message>
        <source>Program %1 was not read. Your edits are kept.</source>
        <translation>Program %1 was not read. Your edits are kept.</translation>
    </message>
    <message>
        <source>Program %1: nothing to write, the device holds what you see.</source>
        <translation>Program %1: nothing to write, the device holds what you see.</translation>
    </message>
    <message>
        <source>Writing program %1…</source>
        <translation>Writing program %1…</translation>
    </message>
    <message numerus="yes">
        <source>%n other output(s) were already as on the device and not sent.</source>
        <translation>
            <numerusform>%n other output was already as on the device and not sent.</numerusform>
            <numerusform>%n other outputs were already as on the device and not sent.</numerusform>
        </translation>
    </message>
    <message>
        <source>Output names and dead times not read: %1 Your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CamTableModel</name>
    <message>
        <source>On</source>
        <translation>On</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Off</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Length</translation>
    </message>
</context>
<context>
    <name>cambench::CamText</name>
    <message>
        <source>no cams</source>
        <translation type="unfinished">no cams</translation>
    </message>
</context>
<context>
    <name>cambench::CapabilityGate</name>
    <message>
        <source>&lt;b&gt;Not available with the connected protocol&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check what the protocol offers</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CheckReportDialog</name>
    <message>
        <source>%1 held, %2 refuted, %3 could not tell (%4 requests sent, all reading). Save the report and send it back, so that our tables can be corrected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check this device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the check report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check report (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The check did not run to its end: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CommissioningReport</name>
    <message>
        <source>Commissioning report</source>
        <translation>Commissioning report</translation>
    </message>
    <message>
        <source>Created %1 with CamBench %2</source>
        <translation>Created %1 with CamBench %2</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <source>Firmware (EPROM date)</source>
        <translation>Firmware (EPROM date)</translation>
    </message>
    <message>
        <source>Device number</source>
        <translation>Device number</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>Outputs / inputs</source>
        <translation>Outputs / inputs</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Programs</translation>
    </message>
    <message>
        <source>Position range</source>
        <translation>Position range</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Settings</translation>
    </message>
    <message>
        <source>Settings not read.</source>
        <translation>Settings not read.</translation>
    </message>
    <message>
        <source>Outputs and dead times</source>
        <translation>Outputs and dead times</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation>Dead time</translation>
    </message>
    <message>
        <source>Program %1</source>
        <translation>Program %1</translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation>Program %1: %2</translation>
    </message>
    <message>
        <source>Cannot write the report to %1: %2</source>
        <translation>Cannot write the report to %1: %2</translation>
    </message>
    <message>
        <source>%1 (device: %2)</source>
        <translation>%1 (device: %2)</translation>
    </message>
    <message>
        <source>Read from the device at %1.</source>
        <translation>Read from the device at %1.</translation>
    </message>
    <message>
        <source>Not read from the device: the values are this PC&apos;s.</source>
        <translation>Not read from the device: the values are this PC&apos;s.</translation>
    </message>
    <message>
        <source>Offline project: the values are this PC&apos;s.</source>
        <translation>Offline project: the values are this PC&apos;s.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) in this report are edited on this PC and NOT written to the device; they are marked %1 and show the device&apos;s value beside them.</source>
        <translation>
            <numerusform>%n value in this report is edited on this PC and NOT written to the device; it is marked %1 and shows the device&apos;s value beside it.</numerusform>
            <numerusform>%n values in this report are edited on this PC and NOT written to the device; they are marked %1 and show the device&apos;s value beside them.</numerusform>
        </translation>
    </message>
    <message>
        <source>Every value in this report is what the device held when it was read.</source>
        <translation>Every value in this report is what the device held when it was read.</translation>
    </message>
    <message>
        <source>Offline project: nothing in this report was read from a device.</source>
        <translation>Offline project: nothing in this report was read from a device.</translation>
    </message>
    <message>
        <source>Identity read at</source>
        <translation>Identity read at</translation>
    </message>
    <message>
        <source>offline project</source>
        <translation>offline project</translation>
    </message>
    <message>
        <source>Project file</source>
        <translation>Project file</translation>
    </message>
    <message>
        <source>0 … %1</source>
        <translation>0 … %1</translation>
    </message>
    <message>
        <source>Not read from the device: its content is unknown.</source>
        <translation>Not read from the device: its content is unknown.</translation>
    </message>
    <message>
        <source>Not read from the device: these cams exist on this PC only.</source>
        <translation>Not read from the device: these cams exist on this PC only.</translation>
    </message>
    <message>
        <source>No cams.</source>
        <translation>No cams.</translation>
    </message>
    <message>
        <source>Cams (on–off)</source>
        <translation>Cams (on–off)</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Users</translation>
    </message>
    <message>
        <source>No users.</source>
        <translation>No users.</translation>
    </message>
    <message>
        <source>User numbers are access codes: they are not printed.</source>
        <translation>User numbers are access codes: they are not printed.</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>Number</translation>
    </message>
    <message>
        <source>Rights</source>
        <translation>Rights</translation>
    </message>
    <message>
        <source>deleted on this PC, still on the device</source>
        <translation>deleted on this PC, still on the device</translation>
    </message>
    <message>
        <source>PLC networks</source>
        <translation>PLC networks</translation>
    </message>
    <message>
        <source>No PLC networks read or edited.</source>
        <translation>No PLC networks read or edited.</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>Network</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Symbols by path</source>
        <translation>Symbols by path</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch-on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch-off / time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal</source>
        <translation type="unfinished">Normal</translation>
    </message>
    <message>
        <source>On/off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Path-time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead-time modes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming program and EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead time on / off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shift on / off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shortest cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Minimum pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 / %2 positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>standing still</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished">none</translation>
    </message>
    <message>
        <source>Timing at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each edge switches early by speed × its dead time, so that the actuator acts at the programmed position. Dead times as in this report (edits included).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings at this speed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read from this device</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CompareDialog</name>
    <message>
        <source>Compare with device</source>
        <translation>Compare with device</translation>
    </message>
    <message>
        <source>Item</source>
        <translation>Item</translation>
    </message>
    <message>
        <source>On the device</source>
        <translation>On the device</translation>
    </message>
    <message>
        <source>Edited on this PC</source>
        <translation>Edited on this PC</translation>
    </message>
    <message>
        <source>Write selected</source>
        <translation>Write selected</translation>
    </message>
    <message>
        <source>Write all</source>
        <translation>Write all</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>No differences: the device holds what you see.</source>
        <translation>No differences: the device holds what you see.</translation>
    </message>
    <message>
        <source>Nothing selected: nothing was written.</source>
        <translation>Nothing selected: nothing was written.</translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>Writing…</translation>
    </message>
    <message>
        <source>Cancel reading</source>
        <translation>Cancel reading</translation>
    </message>
    <message>
        <source>Read the device again</source>
        <translation>Read the device again</translation>
    </message>
    <message>
        <source>Not connected: compared with the device values read at %1. The device may have changed since.</source>
        <translation>Not connected: compared with the device values read at %1. The device may have changed since.</translation>
    </message>
    <message>
        <source>Not connected, and nothing was read from a device: every edited item is listed as &quot;not read&quot;.</source>
        <translation>Not connected, and nothing was read from a device: every edited item is listed as &quot;not read&quot;.</translation>
    </message>
    <message>
        <source>Reading what the device holds now…</source>
        <translation>Reading what the device holds now…</translation>
    </message>
    <message>
        <source>Reading cancelled.</source>
        <translation>Reading cancelled.</translation>
    </message>
    <message>
        <source>The device could not be read: %1</source>
        <translation>The device could not be read: %1</translation>
    </message>
    <message>
        <source>Shown: the device values read at %1.</source>
        <translation>Shown: the device values read at %1.</translation>
    </message>
    <message>
        <source>Nothing was read from the device: edited items are listed as &quot;not read&quot;.</source>
        <translation>Nothing was read from the device: edited items are listed as &quot;not read&quot;.</translation>
    </message>
    <message>
        <source>Device values read at %1.</source>
        <translation>Device values read at %1.</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Not read: %1</translation>
    </message>
    <message>
        <source>Changed on the device since it was last read (%1)</source>
        <translation>Changed on the device since it was last read (%1)</translation>
    </message>
    <message>
        <source>The edits hold a copy of the values of %1, made when this device came on the line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy to write</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CompareProgramsDialog</name>
    <message>
        <source>Compare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hide outputs without a difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare programs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A (before)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B (after)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the same in both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>changed: A dashed, B solid, moved edges marked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only in A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only in B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited on this PC</source>
        <translation type="unfinished">Edited on this PC</translation>
    </message>
    <message>
        <source>On the device</source>
        <translation type="unfinished">On the device</translation>
    </message>
    <message>
        <source>Project file</source>
        <translation type="unfinished">Project file</translation>
    </message>
    <message>
        <source>CSV cam file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File:</source>
        <translation type="unfinished">File:</translation>
    </message>
    <message>
        <source>CSV cam files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench projects (*.json)</source>
        <translation type="unfinished">CamBench projects (*.json)</translation>
    </message>
    <message>
        <source>(none chosen)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 is not on this PC yet: read it from the device or open a project.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edited on this PC, program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read program %1</source>
        <translation type="unfinished">Read program %1</translation>
    </message>
    <message>
        <source>the device, program %1, read at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the project file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, program %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds no program %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the CSV file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>A: %1. B: %2. %n difference(s).</source>
        <translation>
            <numerusform>A: %1. B: %2. %n difference.</numerusform>
            <numerusform>A: %1. B: %2. %n differences.</numerusform>
        </translation>
    </message>
    <message>
        <source>output %1, cam %2: %3 → %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output %1, cam %2 (in B %3): %4 → %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output %1: cam %2 only in A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output %1: cam %2 only in B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write checked to the device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes the checked differences to the device side&apos;s program: its outputs as the device held them, with those differences made like the other side.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 Reading both sides again…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>output %1 (%n difference(s))</source>
        <translation>
            <numerusform>output %1 (%n difference)</numerusform>
            <numerusform>output %1 (%n differences)</numerusform>
        </translation>
    </message>
    <message>
        <source>Write to the device, program %1: %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each output is written whole: as read from the device (%1), with the checked differences made like the other side. Cam outputs switch as soon as the device takes them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output(s) %1 of program %2 hold edits on this PC that are not on the device: they are replaced by what is written (Edit → Undo brings them back).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write checked differences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write to device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply differences from Compare programs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing program %1…</source>
        <translation type="unfinished">Writing program %1…</translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation type="unfinished">Program %1: %2</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Gui</name>
    <message>
        <source>Use dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) typed in on this PC are NOT on the drive; the values below are the drive&apos;s.</source>
        <translation>
            <numerusform>%n value typed in on this PC is NOT on the drive; the values below are the drive&apos;s.</numerusform>
            <numerusform>%n values typed in on this PC are NOT on the drive; the values below are the drive&apos;s.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cambench::Compax3MotionPage</name>
    <message>
        <source>Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 (homing)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog +…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog −…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start set…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog (moves until STOP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Positioning set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every motion asks first. A command that moves the axis is sent once: when its answer is lost, CamBench reads the drive&apos;s state and says it instead of sending it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message>
        <source>Sent: %1. Now %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis moves until STOP (or Escape) is pressed. Make sure nobody is at the axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis is powered and holds its position. Make sure nobody is at the axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on drive %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis moves to the set&apos;s target at its velocity. STOP (or Escape) stops it. Make sure nobody is at the axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stops the drive and drops what waits for the line: the STOP above every page. Escape does the same.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode (1905.n):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion is off while the STOP cannot reach the drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
    <message>
        <source>Read set %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 not read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished">%1 (%2)</translation>
    </message>
    <message>
        <source>Set %1 is not read from the drive yet: reading it; start it then.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 → %3 (written first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deceleration:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (read at %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch drive %1 powerless?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Power is dropped: the motor no longer holds the axis. A hanging (vertical) axis falls unless its brake holds it; a moving axis runs out as the drive is set. Make sure nobody is at the axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 as read from the drive at %2; read again before anything is sent: if the drive then holds other values, nothing is sent and you are asked again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 (as read)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode (1905.%1): %2 (as read)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3ObjectModel</name>
    <message>
        <source>(not in the dictionary)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>function (written only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control word: Motion page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished">Name</translation>
    </message>
    <message>
        <source>On the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stale: read %1, the connection was lost since.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited on this PC, not on the drive yet: Write changes sends it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a new value (decimal point: 12.5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not on this drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive does not have this object: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Typed in, but the dictionary in use refuses it: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3ObjectsPage</name>
    <message>
        <source>Objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write changes…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search objects (number, name, group)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Discard %n value(s) typed in but not written?</source>
        <translation>
            <numerusform>Discard %n value typed in but not written?</numerusform>
            <numerusform>Discard %n values typed in but not written?</numerusform>
        </translation>
    </message>
    <message>
        <source>Load dictionary…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load object dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compax3 dictionaries (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object, e.g. O 1234,5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished">Value</translation>
    </message>
    <message>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Any object by number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation type="unfinished">Not read: %1</translation>
    </message>
    <message numerus="yes">
        <source>Read %n object(s) at %1.</source>
        <translation>
            <numerusform>Read %n object at %1.</numerusform>
            <numerusform>Read %n objects at %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Read %1 objects; the drive refused %2 (hover over &quot;refused&quot; for its answer).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to write: no value is typed in.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to a drive: the values stay typed in.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 → %3</source>
        <translation type="unfinished">%1: %2 → %3</translation>
    </message>
    <message>
        <source>(not read)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Write %n value(s) to the drive %1?</source>
        <translation>
            <numerusform>Write %n value to the drive %1?</numerusform>
            <numerusform>Write %n values to the drive %1?</numerusform>
        </translation>
    </message>
    <message>
        <source>Write objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1100.3 is the control word, which moves the axis: use the Motion page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The dictionary was not loaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) are typed in but not written. Load the dictionary anyway? Values of objects it still lists stay typed in.</source>
        <translation>
            <numerusform>%n value is typed in but not written. Load the dictionary anyway? Values of objects it still lists stay typed in.</numerusform>
            <numerusform>%n values are typed in but not written. Load the dictionary anyway? Values of objects it still lists stay typed in.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Loaded %n object(s) from %1.</source>
        <translation>
            <numerusform>Loaded %n object from %1.</numerusform>
            <numerusform>Loaded %n objects from %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) typed in, not on the drive yet: Write changes sends them.</source>
        <translation>
            <numerusform>%n value typed in, not on the drive yet: Write changes sends it.</numerusform>
            <numerusform>%n values typed in, not on the drive yet: Write changes sends them.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The loaded dictionary refuses %n typed value(s); they stay typed in and are not written until corrected: %1</source>
        <translation>
            <numerusform>The loaded dictionary refuses %n typed value; it stays typed in and is not written until corrected: %1</numerusform>
            <numerusform>The loaded dictionary refuses %n typed values; they stay typed in and are not written until corrected: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n object(s) are not on this drive (greyed).</source>
        <translation>
            <numerusform>%n object is not on this drive (greyed).</numerusform>
            <numerusform>%n objects are not on this drive (greyed).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Nothing was written: the dictionary in use refuses %n typed value(s) (they stay typed in; correct or clear them): %1</source>
        <translation>
            <numerusform>Nothing was written: the dictionary in use refuses %n typed value (it stays typed in; correct or clear it): %1</numerusform>
            <numerusform>Nothing was written: the dictionary in use refuses %n typed values (they stay typed in; correct or clear them): %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Page</name>
    <message>
        <source>Read drive status</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3ParametersPage</name>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No file compared yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write to another drive type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save drive to file…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save drive parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compax3 parameter files (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with file…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write selected differences…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write whole file…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only when you know the objects mean the same on both drive types.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished">Name</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No file was saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1 objects to %2, but the file is incomplete: the drive refused %3 objects.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Incomplete: %1 objects refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1 objects of drive %2 to %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 objects of %3 (serial number %4), saved %5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not compared: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Equal: the drive holds all %1 values of the file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 objects differ.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file is from a drive of type %1, this one is of type %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with a file first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No difference is ticked: nothing to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n selected object(s)</source>
        <translation>
            <numerusform>%n selected object</numerusform>
            <numerusform>%n selected objects</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the whole file (%n object(s))</source>
        <translation>
            <numerusform>the whole file (%n object)</numerusform>
            <numerusform>the whole file (%n objects)</numerusform>
        </translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write %1 of %2 to drive %3?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file is checked against the drive first; then only objects that differ are written, each read back.%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Afterwards the sets are stored in flash.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To replace a drive: save the old drive&apos;s parameters to a file (or take one saved before), connect the new drive, compare it with the file, then write the differences and store the sets.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store the written sets in the drive&apos;s flash afterwards (1904.n = $32)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not on this drive (recorded in the file as absent): %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Never saved, being control words or functions: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not on the file&apos;s drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not compared, being control words or functions a file never writes: %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Report</name>
    <message>
        <source>Last error (550.1): %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status word (1000.3): %1; set: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished">none</translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished">Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished">Value</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not on this drive: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 not read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the drive for the report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read from the drive for this report.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read from the drive at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial number %1, type %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation type="unfinished">Not read: %1</translation>
    </message>
    <message>
        <source>Parameter set</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3StatusPage</name>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge error…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switches the drive off and on again (control word 0, then 1): the rising edge acknowledges the error and powers the axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status word 1 (object 1000.3), bit 0 first. The meanings of the bits and error numbers come from a public client, not from Parker&apos;s manual.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last error:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge the error and power the axis of drive %1?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not acknowledged: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledged; last error now: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished">%1 (%2)</translation>
    </message>
    <message>
        <source>A powerless drive is switched off and on again; it holds its position with power afterwards. A powered drive is left as it is (nothing is sent). Make sure nobody is at the axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledged by the drive; %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3WatchPage</name>
    <message>
        <source>Watch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object to watch, e.g. 680.5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished">Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished">Value</translation>
    </message>
    <message>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a function: it is written, never read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read watched objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refused</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Window</name>
    <message>
        <source>Identify drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, serial number %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No Compax3 identified itself: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unwritten values</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) typed in on the Objects page are not on the drive.</source>
        <translation>
            <numerusform>%n value typed in on the Objects page is not on the drive.</numerusform>
            <numerusform>%n values typed in on the Objects page are not on the drive.</numerusform>
        </translation>
    </message>
    <message>
        <source>Closing drops them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close and drop them</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionIndicator</name>
    <message>
        <source>No answer since %1 (%2)</source>
        <translation>No answer since %1 (%2)</translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionPage</name>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>A serial port, tcp://host:port for a serial device server, or the simulated device.</source>
        <translation>A serial port, tcp://host:port for a serial device server, or the simulated device.</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Refresh</translation>
    </message>
    <message>
        <source>Look for serial ports again</source>
        <translation>Look for serial ports again</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation>Protocol:</translation>
    </message>
    <message>
        <source>Baud rate:</source>
        <translation>Baud rate:</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connect</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Disconnect</translation>
    </message>
    <message>
        <source>Devices on the line</source>
        <translation>Devices on the line</translation>
    </message>
    <message>
        <source>Scan bus</source>
        <translation>Scan bus</translation>
    </message>
    <message>
        <source>Double-click a device to work with it.</source>
        <translation>Double-click a device to work with it.</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <source>Simulated device</source>
        <translation>Simulated device</translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation>Reconnect</translation>
    </message>
    <message>
        <source>Scanning the bus…</source>
        <translation>Scanning the bus…</translation>
    </message>
    <message>
        <source>Identify device</source>
        <translation>Identify device</translation>
    </message>
    <message>
        <source>Bus scan failed: %1</source>
        <translation>Bus scan failed: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n device(s) found</source>
        <translation>
            <numerusform>%n device found</numerusform>
            <numerusform>%n devices found</numerusform>
        </translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Connection</translation>
    </message>
    <message>
        <source>Not connected to %1: %2
Check the port name (a serial port, tcp://host:port for a device server), the protocol and baud rate, the cable and the device&apos;s power, then press Connect again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no port given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find out what is on this port: each device family&apos;s protocols are tried at their usual line settings, with identification queries only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device family:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (not built into this CamBench yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its protocol, simulator and pages are not built yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose or type a port first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect closes the connection to %1 and then tries each device family on %2. Nothing is written to a device; your edits stay. Go on?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detecting on %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect device on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect could not use the port: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Found on %1: %2. The protocol and baud rate are filled in; press Connect to work with it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect was cancelled; nothing answered on %1 so far. Tried:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing answered on %1. Tried:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the cable, the device&apos;s power and its interface settings (for an RS485 bus also the device number), then Detect again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect: nothing answered on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulated device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>• %1, %2: no answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>You are working on the simulated demo device: no machine is attached, and nothing you write here reaches a real device. To work on a machine, choose its port below (or type it: /dev/ttyUSB0, COM3, tcp://host:port), the protocol and the baud rate, then press Connect.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ask every device number of a bus for an answer, or identify the one device of a point-to-point line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identifying the device failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, device number %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reconnect to reach device %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, address %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch to device %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device %1 does not answer on the bus; device %2 does (the bus has %3): CamBench talks to device %2 now.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionStrip</name>
    <message>
        <source>Reconnect now</source>
        <translation>Reconnect now</translation>
    </message>
    <message>
        <source>The connection to %1 is lost.</source>
        <translation>The connection to %1 is lost.</translation>
    </message>
    <message>
        <source>CamBench tries again by itself; your edits are kept.</source>
        <translation>CamBench tries again by itself; your edits are kept.</translation>
    </message>
    <message>
        <source>The device on %1 has not answered since %2.</source>
        <translation>The device on %1 has not answered since %2.</translation>
    </message>
    <message>
        <source>Live values are from then. Check the cable and the device&apos;s power; your edits are kept.</source>
        <translation>Live values are from then. Check the cable and the device&apos;s power; your edits are kept.</translation>
    </message>
    <message>
        <source>%1; identity not read yet.</source>
        <translation>%1; identity not read yet.</translation>
    </message>
    <message>
        <source>Offline. What you edit stays on this PC until you connect and write it.</source>
        <translation>Offline. What you edit stays on this PC until you connect and write it.</translation>
    </message>
    <message>
        <source>Not connected to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no port given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the port, the cable and the device&apos;s power, then connect again; your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message>
        <source>Check that the port and the protocol are this device&apos;s; nothing is written to it. Your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimeModesPage</name>
    <message>
        <source>Dead-time modes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished">Output</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead time (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch-on (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch-off / time (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal: one dead time moves both switching points. On/off: the switch-on and the switch-off point each have their own. Path-time: the output switches on early by the switch-on dead time and stays on for the switching time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading dead-time modes…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read dead-time modes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading dead-time modes failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead-time modes read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal</source>
        <translation type="unfinished">Normal</translation>
    </message>
    <message>
        <source>On/off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Path-time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 dead-time mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read from the device yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation type="unfinished">On the device: %1</translation>
    </message>
    <message>
        <source>Edited, not written to the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest dead time: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read from this device yet.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimesModel</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>Edited, not yet written to the device.</source>
        <translation>Edited, not yet written to the device.</translation>
    </message>
    <message>
        <source>Same as on the device.</source>
        <translation>Same as on the device.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation>Dead time</translation>
    </message>
    <message>
        <source>On the device</source>
        <translation>On the device</translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimesPage</name>
    <message>
        <source>The dead time makes an output switch earlier by the time its actuator needs, at every speed. It belongs to the output, not to a program.</source>
        <translation>The dead time makes an output switch earlier by the time its actuator needs, at every speed. It belongs to the output, not to a program.</translation>
    </message>
    <message>
        <source>Dead times</source>
        <translation>Dead times</translation>
    </message>
    <message>
        <source>Reading dead times…</source>
        <translation>Reading dead times…</translation>
    </message>
    <message>
        <source>Reading dead times failed: %1</source>
        <translation>Reading dead times failed: %1</translation>
    </message>
    <message>
        <source>Dead times read.</source>
        <translation>Dead times read.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>Output %1 dead time</source>
        <translation>Output %1 dead time</translation>
    </message>
    <message>
        <source>Output %1 name</source>
        <translation>Output %1 name</translation>
    </message>
    <message>
        <source>0.1 ms steps, at most %1 (the device&apos;s maximum)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeviceChange</name>
    <message>
        <source>Program %1, output %2: %3 (read from %4: %5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1, output %2: %3 (not read from a device)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 name: &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 name: &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 dead time: %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Setting: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Users: %1 changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC network %1</source>
        <translation type="unfinished">PLC network %1</translation>
    </message>
    <message>
        <source>Output %1 dead-time mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1 cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon %1, device %2, %3 cams programmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device</source>
        <translation type="unfinished">the device</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceChangeDialog</name>
    <message>
        <source>Another device answers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your changes:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another device answers.&lt;br&gt;New device, on the line now: &lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Old device, the values shown were read from it: &lt;b&gt;%2&lt;/b&gt;&lt;br&gt;You changed %3 of those values. What shall the new device&apos;s values be?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take the new device&apos;s values (your changes are dropped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep my changes, each applied to the new device&apos;s values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy the old device&apos;s programs and sections (with your changes): written to the new device only when you write</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeviceChanges</name>
    <message>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <source>Program %1, output %2</source>
        <translation>Program %1, output %2</translation>
    </message>
    <message>
        <source>Program %1 name</source>
        <translation>Program %1 name</translation>
    </message>
    <message>
        <source>Output %1 dead time</source>
        <translation>Output %1 dead time</translation>
    </message>
    <message>
        <source>Output %1 name</source>
        <translation>Output %1 name</translation>
    </message>
    <message>
        <source>Users: the device&apos;s list of users changed.</source>
        <translation>Users: the device&apos;s list of users changed.</translation>
    </message>
    <message>
        <source>PLC network %1 changed.</source>
        <translation>PLC network %1 changed.</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceCheck</name>
    <message>
        <source>Check which device answers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another device answers: nothing read from %1 is shown as this one&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your changes (%1) stay, not written yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A copy of that device&apos;s values waits to be written.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeviceReads</name>
    <message>
        <source>Not taken: your edits and the values shown are unchanged.</source>
        <translation>Not taken: your edits and the values shown are unchanged.</translation>
    </message>
    <message>
        <source>Read device identity</source>
        <translation>Read device identity</translation>
    </message>
    <message>
        <source>Read program %1</source>
        <translation>Read program %1</translation>
    </message>
    <message>
        <source>Read names and dead times</source>
        <translation>Read names and dead times</translation>
    </message>
    <message>
        <source>Read settings</source>
        <translation>Read settings</translation>
    </message>
    <message>
        <source>Read users</source>
        <translation>Read users</translation>
    </message>
    <message>
        <source>Read PLC network</source>
        <translation>Read PLC network</translation>
    </message>
    <message>
        <source>Read everything</source>
        <translation>Read everything</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceSession</name>
    <message>
        <source>Connection to %1 lost, retrying</source>
        <translation>Connection to %1 lost, retrying</translation>
    </message>
    <message>
        <source>Offline</source>
        <translation>Offline</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Connecting to %1…</translation>
    </message>
    <message>
        <source>Connected to the simulated device</source>
        <translation>Connected to the simulated device</translation>
    </message>
    <message>
        <source>Connected to %1</source>
        <translation>Connected to %1</translation>
    </message>
    <message>
        <source>Connect to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished">Disconnect</translation>
    </message>
    <message>
        <source>No device identifies itself on the simulated line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device identifies itself on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checking which device answers on the simulated line…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checking which device answers on %1…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeviceWriter</name>
    <message>
        <source>Write to the device</source>
        <translation>Write to the device</translation>
    </message>
    <message>
        <source>Nothing was written: the device on the line (CamCon %1, device number %2, %3 cams programmed) is not the one the values shown as on the device were read from (CamCon %4, device number %5, %6 cams programmed).
Read the device again or use Compare with device; your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was written: the write was cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The write&apos;s report says nothing of this item: it counts as not written. Read the device to see what it holds.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DialogStop</name>
    <message>
        <source>STOP (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stops every axis and drive CamBench can reach, without a question. %1 does the same and closes this dialog.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP sent…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished">%1 %2</translation>
    </message>
</context>
<context>
    <name>cambench::EditsReplaced</name>
    <message>
        <source>Program %1, output %2: yours %3; the device now holds %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1, output %2: yours %3; the project holds %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 dead time: yours %2 ms; the device now holds %3 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 dead time: yours %2 ms; the project holds %3 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 name: yours &quot;%2&quot;; the device now holds &quot;%3&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 name: yours &quot;%2&quot;; the project holds &quot;%3&quot;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::EepromLockPage</name>
    <message>
        <source>EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unlock the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the same values again and again (from a PLC, every cycle) wears the device&apos;s EEPROM out. Lock it first: changes then stay in RAM only. A complete deletion of the device unlocks it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the EEPROM lock failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State of the EEPROM lock: not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The EEPROM is locked.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The EEPROM is not locked: changes are stored permanently.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changes written now are kept in RAM only. They are lost when the device is switched off. Unlock the EEPROM to keep them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message>
        <source>The project wants the EEPROM locked; not written yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project wants the EEPROM unlocked; not written yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
</context>
<context>
    <name>cambench::LineBackupDialog</name>
    <message>
        <source>Resume: skip devices already saved and verified in this folder</source>
        <translation>Resume: skip devices already saved and verified in this folder</translation>
    </message>
    <message>
        <source>Back up</source>
        <translation>Back up</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Back up all devices on this line</source>
        <translation>Back up all devices on this line</translation>
    </message>
    <message>
        <source>empty: scan the line for devices 0 … 63</source>
        <translation>empty: scan the line for devices 0 … 63</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Browse…</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>Folder:</translation>
    </message>
    <message>
        <source>Devices:</source>
        <translation>Devices:</translation>
    </message>
    <message>
        <source>Each device of the line is backed up into its own image in the folder, with a manifest of what was saved. A device that fails is noted and the others are still backed up.</source>
        <translation>Each device of the line is backed up into its own image in the folder, with a manifest of what was saved. A device that fails is noted and the others are still backed up.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a device number 0 … 63 (or given twice); write the numbers with commas, e.g. 0, 5, 7.</source>
        <translation>&quot;%1&quot; is not a device number 0 … 63 (or given twice); write the numbers with commas, e.g. 0, 5, 7.</translation>
    </message>
    <message>
        <source>%1, %2, %3 baud</source>
        <translation>%1, %2, %3 baud</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>waiting</translation>
    </message>
    <message>
        <source>Scanning the line…</source>
        <translation>Scanning the line…</translation>
    </message>
    <message>
        <source>Backing up…</source>
        <translation>Backing up…</translation>
    </message>
    <message>
        <source>Back up the line</source>
        <translation>Back up the line</translation>
    </message>
    <message>
        <source>Device %1</source>
        <translation>Device %1</translation>
    </message>
    <message>
        <source>Nothing was backed up: %1</source>
        <translation>Nothing was backed up: %1</translation>
    </message>
    <message>
        <source>saved</source>
        <translation>saved</translation>
    </message>
    <message>
        <source>FAILED</source>
        <translation>FAILED</translation>
    </message>
    <message>
        <source>Device %1: saved to %2.</source>
        <translation>Device %1: saved to %2.</translation>
    </message>
    <message>
        <source>Device %1: NOT saved: %2</source>
        <translation>Device %1: NOT saved: %2</translation>
    </message>
    <message numerus="yes">
        <source>All %n device(s) saved into %1.</source>
        <translation>
            <numerusform>The %n device saved into %1.</numerusform>
            <numerusform>All %n devices saved into %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 devices saved; %3 NOT saved (see below). The manifest in %4 says the same.</source>
        <translation>%1 of %2 devices saved; %3 NOT saved (see below). The manifest in %4 says the same.</translation>
    </message>
</context>
<context>
    <name>cambench::LinkSettingsQuestion</name>
    <message>
        <source>Communication settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The values to write include communication settings: %1 (the device has %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>others</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>They decide how the device is reached. Written, the next connection to this device needs them: change the connection settings to match afterwards. Left out, the device keeps its own and everything else is written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Also write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::LiveDevicePage</name>
    <message>
        <source>STOP (Esc)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::LiveFamilyWindow</name>
    <message>
        <source>Connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::LiveFreshness</name>
    <message>
        <source>No live values yet</source>
        <translation>No live values yet</translation>
    </message>
    <message>
        <source>Live, last answer %1</source>
        <translation>Live, last answer %1</translation>
    </message>
    <message>
        <source>No answer since %1</source>
        <translation>No answer since %1</translation>
    </message>
    <message>
        <source>No answer yet</source>
        <translation>No answer yet</translation>
    </message>
    <message>
        <source>Not polled now; values of %1</source>
        <translation>Not polled now; values of %1</translation>
    </message>
    <message>
        <source>Paused (%1); values of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
    <message>
        <source>live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer since %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paused, read %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paused (%1), read %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Machine</name>
    <message>
        <source>The machine has a device named &quot;%1&quot; already; give this one another name.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineBackupRun</name>
    <message numerus="yes">
        <source>… and %n more (Details)</source>
        <translation>
            <numerusform>… and %n more (Details)</numerusform>
            <numerusform>… and %n more (Details)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is not a machine backup folder: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not in this backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not saved in this backup (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its file in the backup changed since it was saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot make the folder %1; check the path and its rights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed: %1 - nothing was saved from it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT SAVED: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(the manifest: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine file in %1 lacks the identities: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not verified: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 - not verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>equal: %n item(s) compared</source>
        <translation>
            <numerusform>equal: %n item compared</numerusform>
            <numerusform>equal: %n items compared</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s):</source>
        <translation>
            <numerusform>%n difference:</numerusform>
            <numerusform>%n differences:</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not restored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the backup of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plan the restore of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s) to change</source>
        <translation>
            <numerusform>%1: %n item to change</numerusform>
            <numerusform>%1: %n items to change</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>plan read: %n item(s) to change</source>
        <translation>
            <numerusform>plan read: %n item to change</numerusform>
            <numerusform>plan read: %n items to change</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore %1 from %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What each device holds is saved beside the backup folder first. Then this is written:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore</source>
        <translation type="unfinished">Restore</translation>
    </message>
    <message>
        <source>not restored: cancelled, nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not restored: cannot make the folder %1 for the safety copies; nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT RESTORED completely: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>safety copies of a restore from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The safety copies in %1 are not listed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the devices held before: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineHistoryDialog</name>
    <message>
        <source>equal</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>equal (%n change(s) of volatile items left out)</source>
        <translation>
            <numerusform>equal (%n change of volatile items left out)</numerusform>
            <numerusform>equal (%n changes of volatile items left out)</numerusform>
        </translation>
    </message>
    <message>
        <source>added: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>taken out of the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT COMPARED: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Compare the two</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with the devices &amp;now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Restore this version…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Mark as released</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>History of %1 - %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Who</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Why</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Released</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished">Device</translation>
    </message>
    <message>
        <source>Item</source>
        <translation type="unfinished">Item</translation>
    </message>
    <message>
        <source>Before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>released</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds no version yet: Machine → Back up… into it, or `cambench-cli machine backup M.json --archive %1 -m WHY`.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machine file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no difference.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: differences in %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not every device was compared (see the table).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading every device to compare it with version %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version %1 → the devices now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version %1 is the released version now (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading each device&apos;s plan of restoring version %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: NOT RESTORED: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s) to change
</source>
        <translation>
            <numerusform>%1: %n item to change
</numerusform>
            <numerusform>%1: %n items to change
</numerusform>
        </translation>
    </message>
    <message>
        <source>Version %1 is not restored: no device can take it.
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore version %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore version %1 into %2? Each device&apos;s plan is in the details; a safety copy of what a device holds is taken first where its family takes one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version %1 was not restored; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore of version %1:
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The archive of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Draw the differences…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>version %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 → %3</source>
        <translation type="unfinished">%1: %2 → %3</translation>
    </message>
    <message>
        <source>Drawn as well: %1 (Draw the differences…, or a double click on its row).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device&apos;s changes between the two states compared (two versions, or a version and the devices now), drawn in its family&apos;s terms (a double click on its row does the same); a table is all there is for a family that draws none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the devices now</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineHistoryJobs</name>
    <message>
        <source>NOT RESTORED: cannot make the folder %1 for the safety copies; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT RESTORED: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT RESTORED completely: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not in this version of the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message>
        <source>Nothing will be written to it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was written to it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed: no temporary folder for the backup now: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: back up to compare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineReport</name>
    <message>
        <source>not identified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>never</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine report: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Made %1 by CamBench.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished">Device</translation>
    </message>
    <message>
        <source>Family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line</source>
        <translation type="unfinished">Line</translation>
    </message>
    <message>
        <source>Identity</source>
        <translation type="unfinished">Identity</translation>
    </message>
    <message>
        <source>Not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished">%1 (%2)</translation>
    </message>
    <message>
        <source>Identity: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line: %1 on %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edits on this PC not written to the device: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recorded identity: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last answered: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read: %1; its section says what this PC holds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineReportChanges</name>
    <message>
        <source>%1: version %2 of %3 by %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>version %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>equal to the released version</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>equal to the released version (%n change(s) of volatile items left out)</source>
        <translation>
            <numerusform>equal to the released version (%n change of volatile items left out)</numerusform>
            <numerusform>equal to the released version (%n changes of volatile items left out)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>DIFFERS: %n difference(s)</source>
        <translation>
            <numerusform>DIFFERS: %n difference</numerusform>
            <numerusform>DIFFERS: %n differences</numerusform>
        </translation>
    </message>
    <message>
        <source>not in the released version: not compared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in the released version, but no longer a device of this machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT COMPARED: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changes since the released version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not part of this report: no machine archive was chosen.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Archive: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was compared: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Released version: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each device was read for this report and compared with its backup in that version.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished">Device</translation>
    </message>
    <message>
        <source>Since the released version</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineStop</name>
    <message>
        <source>not connected: the STOP was not sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acknowledged by %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT acknowledged by %1 – use the machine&apos;s emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>could not reach %1 – use the machine&apos;s emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineUnit</name>
    <message>
        <source>not opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gone, retrying: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation type="unfinished">not connected: %1</translation>
    </message>
    <message>
        <source>not connected yet: choose its port on its Connection page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline</source>
        <translation type="unfinished">offline</translation>
    </message>
    <message>
        <source>Watch the line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check which device answers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another device answers: no %1 identifies itself (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer since %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer since %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected, %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>checking which device answers…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>did not identify itself: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MachineWindow</name>
    <message>
        <source>Device</source>
        <translation type="unfinished">Device</translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished">State</translation>
    </message>
    <message>
        <source>Not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Add device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save machine as…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine &amp;report…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: connection lost (%2); the other devices are not affected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench – machine %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>[%n change(s) not written]</source>
        <translation>
            <numerusform>[%n change not written]</numerusform>
            <numerusform>[%n changes not written]</numerusform>
        </translation>
    </message>
    <message>
        <source>Save machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine file (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine saved to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine report written to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name of the device in this machine (e.g. feed):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: choose its port on its Connection page (Detect finds the protocol), then Connect.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Back up…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up the machine into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Why (kept in the backup&apos;s manifest):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Verify…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify against the backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R&amp;estore…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore the backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;History…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the changes since the released version? Each device is then compared with its backup in the version released in the machine&apos;s archive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the archive…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Without</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The archive of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not compared: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Edit</translation>
    </message>
    <message>
        <source>&amp;Device</source>
        <translation>&amp;Device</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Connect</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>&amp;Dark palette</source>
        <translation>&amp;Dark palette</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Language</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>&amp;About CamBench</source>
        <translation>&amp;About CamBench</translation>
    </message>
    <message>
        <source>About CamBench</source>
        <translation>About CamBench</translation>
    </message>
    <message>
        <source>CamBench – %1</source>
        <translation>CamBench – %1</translation>
    </message>
    <message numerus="yes">
        <source>[%n change(s) not written]</source>
        <translation>
            <numerusform>[%n change not written]</numerusform>
            <numerusform>[%n changes not written]</numerusform>
        </translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Connection lost: %1</translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation>Not connected: %1</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Cancel what the device is doing for you now.</source>
        <translation>Cancel what the device is doing for you now.</translation>
    </message>
    <message>
        <source>&amp;Last write report…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last write (%1): complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last write (%1): NOT complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the report of the last write: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (written at %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identify device</source>
        <translation type="unfinished">Identify device</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device did not identify itself: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;CamBench %1&lt;/b&gt;&lt;p&gt;Programming, monitoring and backup of machine controllers: %2.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No page of CamBench knows the devices of this protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection re-established: the same device answers. Your edits are unchanged; Compare with device reads what the device holds now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection re-established, but another device answers on this port: see the note at the top.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Check this device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stops every axis and drive of every device of the machine, without a question. %1 does the same from every page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;machine…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New mac&amp;hine…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;demo machine</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1AxesPage</name>
    <message>
        <source>Axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move (each asks first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog −</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog +</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The %1 has no axis telegrams: moving axes needs an MC200 V2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to an MC100/MC200.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis moves until STOP (or Escape) is pressed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis moves at its set speed. STOP (or Escape) stops it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on the %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stops every axis and drops what waits for the line: the STOP above every page. Escape does the same.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moves are off while the STOP cannot reach the %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1 is jogging %2 (now at %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which axes the controller has could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller has no axes (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axes %1 (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position %1 · %2 · %3 · %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jogging %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation type="unfinished">Not read: %1</translation>
    </message>
    <message>
        <source>Done: %1 (the controller acknowledged it). Now %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the speed of axis %1 to %2 on the %3?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller moves the axis at this speed from now on.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1AxisParametersBox</name>
    <message>
        <source>Load parameter table…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A CSV file of name,axis,parameter lines (name: position, target or status) from the controller&apos;s MC-1B manual: the RDSTAT parameter numbers of its axes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load parameter table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 was not loaded: %2
The table in use stays: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The table loaded last (%1) could not be read again: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use parameter table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis parameter numbers: provisional (%1). Positions and states read through them are not facts: load the controller&apos;s parameter table.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis parameter numbers: from %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1MemoryPage</name>
    <message>
        <source>Memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bytes in hex, e.g. 0a 0b 0c</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write (MC200 V2; asks first, then reads back)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the bytes as pairs of hex digits, e.g. 0a 0b 0c.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The %1 has no memory telegrams (an MC200 has).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 bytes read from 0x%2 at %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Write %n byte(s) at %1 of the %2?</source>
        <translation>
            <numerusform>Write %n byte at %1 of the %2?</numerusform>
            <numerusform>Write %n bytes at %1 of the %2?</numerusform>
        </translation>
    </message>
    <message>
        <source>The controller uses its memory at once; a wrong byte can stop its program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Written at %1 and read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Written at %1, but the bytes read back differ.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1Page</name>
    <message>
        <source>Done: %1 (the controller acknowledged it). Reading back failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1PointsPage</name>
    <message>
        <source>Flags &amp; I/O</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs (E)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs (A) - click to set or clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flags (M) - click to set or clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read flags and I/O</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 on the %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear %1 on the %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The output switches at once; whatever it drives on the machine acts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PLC program sees the flag at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished">Clear</translation>
    </message>
    <message>
        <source>Write flag or output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2, read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 reads back %2 after the write.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1ProgramPage</name>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PLC program runs: outputs and axes follow it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PLC program stops where it is; outputs keep their state.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One instruction of the PLC program runs; it may switch an output or start an axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller restarts: axes stop, outputs drop, the PLC program starts again from the beginning.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller&apos;s flash is overwritten with what it holds now. What the flash held before is lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller&apos;s variables are replaced by those in its flash. Values changed since the last save are lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save to flash…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load from flash…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The %1 has no program telegrams: status and control need an MC200 V2 (SYSDATA). Variables, flags and I/O work.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to an MC100/MC200.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC program: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read program status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on the %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Done: %1. PLC program %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control (each asks first)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1Report</name>
    <message>
        <source>%1 variables read (V%2 to V%3); %4 of them are 0 and not listed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The flags were not read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All %1 external flags are clear.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Of %1 external flags, these %2 are set: %3. All others are clear.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter table in use: %1 - PROVISIONAL parameter numbers (a guess, not from the controller&apos;s documentation): the axis values above are not facts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter table in use: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished">Axis</translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished">Value</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the controller for the report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 reports no program state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 has no axis telegrams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read from the controller for this report.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read from the controller at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identity: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation type="unfinished">Not read: %1</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No axis read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>standing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished">Position</translation>
    </message>
    <message>
        <source>Target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished">State</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axes: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>External flags</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1SettingsWidget</name>
    <message>
        <source>Automatic (probe the controller)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic asks the controller and names what it found. A variant chosen here is checked against what answers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RS232, 8N1. MC100: 9600 baud, RxD/TxD crossed. MC200: the baud rate set in the controller, a 1:1 cable; CamBench holds DTR high and RTS low, which power its interface.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>found by asking the controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Empty: an MC200 is asked which axes it has (RDTABLE), and STOP goes to each of them. Axis numbers such as 1,2 name them instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axes:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1TrendPage</name>
    <message>
        <source>Trend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The first eight variables of the Variables page&apos;s watch list, read while this page or that one is shown.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1VariablesPage</name>
    <message>
        <source>Variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Watch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import names…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A CSV file of &quot;number;name&quot; lines, e.g. from the PLC program&apos;s variable list. The names stay on this PC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import variable names</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s) added to the watch list.</source>
        <translation>
            <numerusform>%n variable added to the watch list.</numerusform>
            <numerusform>%n variables added to the watch list.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 could not be read: %2. Nothing was imported.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a name list (%2). Nothing was imported.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n name(s) imported from %1.</source>
        <translation>
            <numerusform>%n name imported from %1.</numerusform>
            <numerusform>%n names imported from %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Read variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to an MC100/MC200: nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write V%1 = %2 to the %3?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller&apos;s PLC program uses this variable at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V%1 was not written: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V%1 = %2 written and read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V%1 reads back %2, not the %3 written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open list…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A watch list saved before (MC-1 project file): its variables, names and the values they had then, shown as not read until read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save list…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The watch list with its names and the values last read, as an MC-1 project file on this PC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open watch list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC-1 projects (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save watch list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Watch list saved to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The watch list was not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s) from %1; values shown as in the file until read.</source>
        <translation>
            <numerusform>%n variable from %1; values shown as in the file until read.</numerusform>
            <numerusform>%n variables from %1; values shown as in the file until read.</numerusform>
        </translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a whole number: V%2 was not written.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1WatchModel</name>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
    <message>
        <source>stale, read %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double-click to write a new value to the controller (it asks first).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name (on this PC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished">Value</translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished">State</translation>
    </message>
    <message>
        <source>line %1: &quot;%2&quot; is not &quot;number;name&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: variable numbers end at 65535</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>from the file, not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restored from last session, not read yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on the controller: %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::Mc1Window</name>
    <message>
        <source>Identify controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No MC100/MC200 identified itself: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up controller (variables, flags)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC-1 backups (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify controller against backup…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify against backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore backup to controller…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup</source>
        <translation type="unfinished">Backup</translation>
    </message>
    <message>
        <source>No backup was saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1 variables and %2 flags to %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not verified: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller holds all %1 values of %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s) between the controller and %1:</source>
        <translation>
            <numerusform>%n difference between the controller and %1:</numerusform>
            <numerusform>%n differences between the controller and %1:</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore</source>
        <translation type="unfinished">Restore</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore %1 (taken %2) to the controller?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>It is checked against the controller first; then only the variables, flags and memory that differ are written. The PLC program uses them at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore controller</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MonitorPage</name>
    <message>
        <source>Monitor</source>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Reset error</source>
        <translation>Reset error</translation>
    </message>
    <message>
        <source>Pause trend</source>
        <translation>Pause trend</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>Position:</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Speed:</translation>
    </message>
    <message>
        <source>Active program:</source>
        <translation>Active program:</translation>
    </message>
    <message>
        <source>Activate</source>
        <translation>Activate</translation>
    </message>
    <message>
        <source>Make this program the active one on the device.</source>
        <translation>Make this program the active one on the device.</translation>
    </message>
    <message>
        <source>Switch to program:</source>
        <translation>Switch to program:</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>State:</translation>
    </message>
    <message>
        <source>Outputs and inputs</source>
        <translation>Outputs and inputs</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Inputs</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Poll every</source>
        <translation>Poll every</translation>
    </message>
    <message>
        <source>Select program</source>
        <translation>Select program</translation>
    </message>
    <message>
        <source>Program %1 is active.</source>
        <translation>Program %1 is active.</translation>
    </message>
    <message>
        <source>Program %1 not activated: %2</source>
        <translation>Program %1 not activated: %2</translation>
    </message>
    <message>
        <source>Error reset sent.</source>
        <translation>Error reset sent.</translation>
    </message>
    <message>
        <source>Error not reset: %1</source>
        <translation>Error not reset: %1</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Actual-value error %1: check the encoder and its cable, then reset.</source>
        <translation>Actual-value error %1: check the encoder and its cable, then reset.</translation>
    </message>
    <message>
        <source>Output error: an output is overloaded or short-circuited; fix it, then reset.</source>
        <translation>Output error: an output is overloaded or short-circuited; fix it, then reset.</translation>
    </message>
    <message>
        <source>EEPROM checksum error: the stored data are damaged; restore a backup.</source>
        <translation>EEPROM checksum error: the stored data are damaged; restore a backup.</translation>
    </message>
    <message>
        <source>Unknown error state %1</source>
        <translation>Unknown error state %1</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>offline</translation>
    </message>
    <message>
        <source>How often the device is asked for its state. CamBench polls no faster than the line can answer.</source>
        <translation>How often the device is asked for its state. CamBench polls no faster than the line can answer.</translation>
    </message>
    <message>
        <source>The line needs about %1 ms per poll: polling every %2 ms instead of %3 ms.</source>
        <translation>The line needs about %1 ms per poll: polling every %2 ms instead of %3 ms.</translation>
    </message>
    <message>
        <source>Waiting for the first answer.</source>
        <translation>Waiting for the first answer.</translation>
    </message>
    <message>
        <source>Offline: no live values.</source>
        <translation>Offline: no live values.</translation>
    </message>
    <message>
        <source>Live: last answer at %1.</source>
        <translation>Live: last answer at %1.</translation>
    </message>
    <message>
        <source>No answer since %1. The values below are from then, not live.</source>
        <translation>No answer since %1. The values below are from then, not live.</translation>
    </message>
    <message>
        <source>No answer from the device.</source>
        <translation>No answer from the device.</translation>
    </message>
    <message>
        <source>Not polled: the values below are from %1.</source>
        <translation>Not polled: the values below are from %1.</translation>
    </message>
    <message>
        <source>Not polled: no live values.</source>
        <translation>Not polled: no live values.</translation>
    </message>
    <message>
        <source>Value of %1</source>
        <translation>Value of %1</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>unknown now; at %1: %2</source>
        <translation>unknown now; at %1: %2</translation>
    </message>
</context>
<context>
    <name>cambench::MotionLeaveQuestion</name>
    <message>
        <source>On the device something moves or is powered:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench could not tell whether something on the device moves or is powered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP, then %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 without stopping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The STOP was not acknowledged everywhere, so CamBench stays connected and STOP can be pressed again. Use the machine&apos;s emergency stop.

%1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MotionStop</name>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ask what moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected: the STOP was not sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it has nothing CamBench can stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device is not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device has nothing CamBench can stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no report of the STOP within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP acknowledged by every axis and drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP NOT acknowledged everywhere – use the machine&apos;s emergency stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: acknowledged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: NOT acknowledged – use the machine&apos;s emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing answered the STOP – use the machine&apos;s emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP acknowledged at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>may move: STOP NOT acknowledged at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>moving (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>standing (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>may move (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>may move: moving when last read at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>may move: %1 sent at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to stop: nothing was powered, and nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished">%1: %2</translation>
    </message>
    <message>
        <source>%1: not powered, nothing to stop</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MultiTrendChart</name>
    <message>
        <source>seconds</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::NewProjectDialog</name>
    <message>
        <source>New project</source>
        <translation>New project</translation>
    </message>
    <message>
        <source>Outputs (multiple of 8):</source>
        <translation>Outputs (multiple of 8):</translation>
    </message>
    <message>
        <source>Inputs (multiple of 8):</source>
        <translation>Inputs (multiple of 8):</translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation>Programs:</translation>
    </message>
    <message>
        <source>Smallest position (IMIN):</source>
        <translation>Smallest position (IMIN):</translation>
    </message>
    <message>
        <source>Largest position (IMAX):</source>
        <translation>Largest position (IMAX):</translation>
    </message>
    <message>
        <source>Outputs with dead time:</source>
        <translation>Outputs with dead time:</translation>
    </message>
</context>
<context>
    <name>cambench::PlcCouplingPage</name>
    <message>
        <source>PLC coupling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An S7 with a CP340 drives the CamCon with the short commands 0x01 to 0x07. This page sends the same telegrams as the function block and shows the answers as the data block holds them. When the CamCon answers here as expected, look for the fault in the PLC program or the CP340&apos;s settings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read status (0x01)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset errors (0x02)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change program (0x03)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area 1: status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On</source>
        <translation type="unfinished">On</translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished">Off</translation>
    </message>
    <message>
        <source>Read cams (0x04)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write cams (0x05)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area 2: cam table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"> ms</translation>
    </message>
    <message>
        <source>Read dead time (0x06)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write dead time (0x07)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area 3: dead times (of the output above)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>outputs %1–%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A PLC program reading the status sees: actual value %1, speed %2, program %3 active, device status %4, %5 outputs, %6. To change the program it writes the wanted number into DW 34; the function block sends 0x03 while DW 14 and DW 34 differ.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none of them on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the status (0x01)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read: the status is unknown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset the errors (0x02)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch the CamCon to program %1 (0x03)? Its outputs follow the cams of program %1 at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the program (0x03)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the cams (0x04)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1, output %2: %3 cams as a PLC reads them (DB+0 AUSG_NR %2, DB+1 ANZ_NOCKEN %3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replace the cams of output %1 in program %2 by the %3 cams shown (0x05)? If program %2 runs, output %1 switches by them at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the cams (0x05)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the dead time (0x06)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read: the dead time is unknown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the dead time of output %1 to %2 (0x07)? The output switches that much earlier from now on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the dead time (0x07)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
    <message>
        <source>Read at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter the dead time to write first (or read it from the device).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::PlcMatrixModel</name>
    <message>
        <source>Path %1, symbol %2: word %3 (provisional decoding: high byte operand kind, low byte number; enter 4 hex digits or e.g. M11)</source>
        <translation>Path %1, symbol %2: word %3 (provisional decoding: high byte operand kind, low byte number; enter 4 hex digits or e.g. M11)</translation>
    </message>
    <message>
        <source>Symbol %1</source>
        <translation>Symbol %1</translation>
    </message>
    <message>
        <source>Path %1</source>
        <translation>Path %1</translation>
    </message>
</context>
<context>
    <name>cambench::PlcPage</name>
    <message>
        <source>O – physical outputs</source>
        <translation>O – physical outputs</translation>
    </message>
    <message>
        <source>P – cam controller inputs</source>
        <translation>P – cam controller inputs</translation>
    </message>
    <message>
        <source>M – flags</source>
        <translation>M – flags</translation>
    </message>
    <message>
        <source>X – X flags</source>
        <translation>X – X flags</translation>
    </message>
    <message>
        <source>Read network</source>
        <translation>Read network</translation>
    </message>
    <message>
        <source>Area:</source>
        <translation>Area:</translation>
    </message>
    <message>
        <source>Number:</source>
        <translation>Number:</translation>
    </message>
    <message>
        <source>Preset of a timer or counter driving this output.</source>
        <translation>Preset of a timer or counter driving this output.</translation>
    </message>
    <message>
        <source>Reset field for counters, 4 hex digits.</source>
        <translation>Reset field for counters, 4 hex digits.</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>Network</translation>
    </message>
    <message>
        <source>Value (timer/counter):</source>
        <translation>Value (timer/counter):</translation>
    </message>
    <message>
        <source>Reset field (hex):</source>
        <translation>Reset field (hex):</translation>
    </message>
    <message>
        <source>Symbols are decoded provisionally (high byte operand kind, low byte number; empty = 0000). Unknown words are shown as hex; every cell accepts 4 hex digits or a form like M11.</source>
        <translation>Symbols are decoded provisionally (high byte operand kind, low byte number; empty = 0000). Unknown words are shown as hex; every cell accepts 4 hex digits or a form like M11.</translation>
    </message>
    <message>
        <source>Networks read or edited in this session</source>
        <translation>Networks read or edited in this session</translation>
    </message>
    <message>
        <source>Reading %1 failed: %2</source>
        <translation>Reading %1 failed: %2</translation>
    </message>
    <message>
        <source>%1 read.</source>
        <translation>%1 read.</translation>
    </message>
    <message>
        <source>Network %1</source>
        <translation>Network %1</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>PLC</source>
        <translation>PLC</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::ProgrammingProgramPage</name>
    <message>
        <source>Programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slow</source>
        <translation type="unfinished">Slow</translation>
    </message>
    <message>
        <source>Direct (within one cycle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At the actual value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The table interface reads and writes the cams of this program. It need not be the program that runs the machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program selection:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Selection actual value:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the programming program failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation type="unfinished">On the device: %1</translation>
    </message>
    <message>
        <source>Not read from the device yet: the values shown are not the device&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited, not written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As on the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From the project, not read from the device: write it or read the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished">not read</translation>
    </message>
</context>
<context>
    <name>cambench::ProgressPage</name>
    <message>
        <source>about %1 min %2 s left</source>
        <translation>about %1 min %2 s left</translation>
    </message>
    <message>
        <source>about %1 s left</source>
        <translation>about %1 s left</translation>
    </message>
    <message>
        <source>%1 s so far. No time left is given: how much the device holds is not known before it is read.</source>
        <translation>%1 s so far. No time left is given: how much the device holds is not known before it is read.</translation>
    </message>
</context>
<context>
    <name>cambench::RangeDelegate</name>
    <message>
        <source>%1%2 is not taken: this device allows %3 … %4%2.</source>
        <translation>%1%2 is not taken: this device allows %3 … %4%2.</translation>
    </message>
    <message>
        <source>The cell keeps its value.</source>
        <translation>The cell keeps its value.</translation>
    </message>
</context>
<context>
    <name>cambench::ReplaceEditsDialog</name>
    <message>
        <source>Cam programs</source>
        <translation>Cam programs</translation>
    </message>
    <message>
        <source>Output names and dead times</source>
        <translation>Output names and dead times</translation>
    </message>
    <message>
        <source>Encoder and system settings</source>
        <translation>Encoder and system settings</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Users</translation>
    </message>
    <message>
        <source>PLC networks</source>
        <translation>PLC networks</translation>
    </message>
    <message>
        <source>Values read from the device</source>
        <translation>Values read from the device</translation>
    </message>
    <message>
        <source>Values from the project file</source>
        <translation>Values from the project file</translation>
    </message>
    <message>
        <source>The device&apos;s values would replace edits that are not written yet. For each section: keep your edits, or take the device&apos;s values?</source>
        <translation>The device&apos;s values would replace edits that are not written yet. For each section: keep your edits, or take the device&apos;s values?</translation>
    </message>
    <message>
        <source>The project&apos;s values would replace edits that are not written yet. For each section: keep your edits, or take the project&apos;s values?</source>
        <translation>The project&apos;s values would replace edits that are not written yet. For each section: keep your edits, or take the project&apos;s values?</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n edit(s)</source>
        <translation>
            <numerusform>%1: %n edit</numerusform>
            <numerusform>%1: %n edits</numerusform>
        </translation>
    </message>
    <message>
        <source>Keep my edits</source>
        <translation>Keep my edits</translation>
    </message>
    <message>
        <source>Take the device&apos;s values</source>
        <translation>Take the device&apos;s values</translation>
    </message>
    <message>
        <source>Take the project&apos;s values</source>
        <translation>Take the project&apos;s values</translation>
    </message>
    <message>
        <source>Items you did not edit take the device&apos;s values either way. Taking the device&apos;s cam programs can be undone (Edit → Undo).</source>
        <translation>Items you did not edit take the device&apos;s values either way. Taking the device&apos;s cam programs can be undone (Edit → Undo).</translation>
    </message>
    <message>
        <source>Items you did not edit take the project&apos;s values either way.</source>
        <translation>Items you did not edit take the project&apos;s values either way.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Apply</translation>
    </message>
    <message>
        <source>Cancel: change nothing</source>
        <translation>Cancel: change nothing</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… and %n more</numerusform>
            <numerusform>… and %n more</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cambench::SettingField</name>
    <message>
        <source>%1 … %2%3, steps of %4</source>
        <translation>%1 … %2%3, steps of %4</translation>
    </message>
    <message>
        <source>%1 … %2%3</source>
        <translation>%1 … %2%3</translation>
    </message>
    <message>
        <source>output 1 … %1, 0 = none</source>
        <translation>output 1 … %1, 0 = none</translation>
    </message>
    <message>
        <source>input 1 … %1, 0 = none</source>
        <translation>input 1 … %1, 0 = none</translation>
    </message>
    <message numerus="yes">
        <source>up to %n character(s)</source>
        <translation>
            <numerusform>up to %n character</numerusform>
            <numerusform>up to %n characters</numerusform>
        </translation>
    </message>
    <message>
        <source>Range: %1</source>
        <translation>Range: %1</translation>
    </message>
    <message>
        <source>Manual section %1</source>
        <translation>Manual section %1</translation>
    </message>
    <message>
        <source>Read only: shown as the device reports it.</source>
        <translation>Read only: shown as the device reports it.</translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation>(not set)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>unknown (%1)</source>
        <translation>unknown (%1)</translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation>On the device: %1</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>Not allowed: %1.</source>
        <translation>Not allowed: %1.</translation>
    </message>
    <message>
        <source>The device holds a value outside the allowed range: %1. It is shown as the device has it, not changed.</source>
        <translation>The device holds a value outside the allowed range: %1. It is shown as the device has it, not changed.</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished">%1 ms</translation>
    </message>
</context>
<context>
    <name>cambench::SettingsPage</name>
    <message>
        <source>SSI encoder</source>
        <translation>SSI encoder</translation>
    </message>
    <message>
        <source>Parallel encoder</source>
        <translation>Parallel encoder</translation>
    </message>
    <message>
        <source>Incremental encoder</source>
        <translation>Incremental encoder</translation>
    </message>
    <message>
        <source>Multi-turn encoder</source>
        <translation>Multi-turn encoder</translation>
    </message>
    <message>
        <source>PLL (pulse multiplier)</source>
        <translation>PLL (pulse multiplier)</translation>
    </message>
    <message>
        <source>Time-based axis</source>
        <translation>Time-based axis</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>Encoder</translation>
    </message>
    <message>
        <source>Actual-value adaptation</source>
        <translation>Actual-value adaptation</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
    </message>
    <message>
        <source>Cycle and timing</source>
        <translation>Cycle and timing</translation>
    </message>
    <message>
        <source>Special outputs</source>
        <translation>Special outputs</translation>
    </message>
    <message>
        <source>Device configuration</source>
        <translation>Device configuration</translation>
    </message>
    <message>
        <source>PLC configuration</source>
        <translation>PLC configuration</translation>
    </message>
    <message>
        <source>Special encoder</source>
        <translation>Special encoder</translation>
    </message>
    <message>
        <source>Analogue outputs</source>
        <translation>Analogue outputs</translation>
    </message>
    <message>
        <source>Program selection</source>
        <translation>Program selection</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Display</translation>
    </message>
    <message>
        <source>Interface</source>
        <translation>Interface</translation>
    </message>
    <message>
        <source>Identity</source>
        <translation>Identity</translation>
    </message>
    <message>
        <source>Expansion modules</source>
        <translation>Expansion modules</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Language</translation>
    </message>
    <message>
        <source>Reading settings…</source>
        <translation>Reading settings…</translation>
    </message>
    <message>
        <source>Reading settings failed: %1</source>
        <translation>Reading settings failed: %1</translation>
    </message>
    <message>
        <source>Settings read.</source>
        <translation>Settings read.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>Encoder &amp; system</source>
        <translation>Encoder &amp; system</translation>
    </message>
</context>
<context>
    <name>cambench::Shell</name>
    <message>
        <source>Open machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine file (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open demo machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name of the machine:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the machine&apos;s devices: Machine → Add device…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::StopBar</name>
    <message>
        <source>STOP (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP sent…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2
%3</source>
        <translation type="unfinished">%1 %2
%3</translation>
    </message>
    <message>
        <source>Stops every axis and drive of the device, without a question, ahead of everything waiting for the line. %1 stops it too, from every window, dialog and menu of CamBench.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::TableSettingsWidget</name>
    <message>
        <source>3964R n96 (9600 baud, 8N1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R e38 (38400 baud, 8E1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The serial mode the device&apos;s menu &quot;Ser:&quot; shows.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point to point: no device number. 3964R e38 reaches only the data words 0–127 of each area: 62 cams per track and no dead-time modes; n96 reaches all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variant:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::TerminalPage</name>
    <message>
        <source>Follow</source>
        <translation>Follow</translation>
    </message>
    <message>
        <source>e.g. ?IFGWG or ?NF000003 — checksum and CR LF are added</source>
        <translation>e.g. ?IFGWG or ?NF000003 — checksum and CR LF are added</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Send</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>Command:</translation>
    </message>
    <message>
        <source>Save log…</source>
        <translation>Save log…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <source>Traffic (user numbers masked)</source>
        <translation>Traffic (user numbers masked)</translation>
    </message>
    <message>
        <source>Save traffic log</source>
        <translation>Save traffic log</translation>
    </message>
    <message>
        <source>Text files (*.txt *.log)</source>
        <translation>Text files (*.txt *.log)</translation>
    </message>
    <message>
        <source>A command starts with ? (query) or ! (command), then its letters and data, e.g. ?IFGWG.</source>
        <translation>A command starts with ? (query) or ! (command), then its letters and data, e.g. ?IFGWG.</translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation>Terminal</translation>
    </message>
    <message>
        <source>&lt; error: %1</source>
        <translation>&lt; error: %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
</context>
<context>
    <name>cambench::TimingBar</name>
    <message>
        <source>Program %1 has no cams.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>At %1: %n warning(s). %2</source>
        <translation>
            <numerusform>At %1: %n warning. %2</numerusform>
            <numerusform>At %1: %n warnings. %2</numerusform>
        </translation>
    </message>
    <message>
        <source>At %1 every cam switches as drawn. First limit: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At %1 every cam switches as drawn, at any speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device&apos;s speed is no longer live; shown at the last speed read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timing at speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draws under every output where it really switches at this speed: the device switches each edge early by speed × dead time so that the actuator acts at the programmed position. Durations in ms; warnings where cams vanish, merge or are shorter than the output&apos;s minimum pulse (track table).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow the speed the device measures, live.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device&apos;s speed is shown while the monitor reads it live (connected, Monitor or diagram polling).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::TrackTableModel</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unchanged</translation>
    </message>
    <message>
        <source>edited</source>
        <translation>edited</translation>
    </message>
    <message>
        <source>Output %1 is the same as on the device.</source>
        <translation>Output %1 is the same as on the device.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation>Dead time</translation>
    </message>
    <message>
        <source>Cams</source>
        <translation>Cams</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>Program %1 was not read from the device: what the device holds is unknown. The cams shown exist on this PC.</source>
        <translation>Program %1 was not read from the device: what the device holds is unknown. The cams shown exist on this PC.</translation>
    </message>
    <message>
        <source>The shortest time output %1 must stay on for its actuator to act. The timing view warns where a cam is on for less at the speed chosen. Kept on this PC and in the project file, not on the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min. pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cams of output %1 were changed and are not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The name of output %1 was changed and is not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The dead time of output %1 was changed and is not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cams of output %1 are the same as on the device. Its name and dead time were not read from it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::TrendChart</name>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Time (s)</translation>
    </message>
</context>
<context>
    <name>cambench::UsersModel</name>
    <message>
        <source>program selection</source>
        <translation>program selection</translation>
    </message>
    <message>
        <source>programming</source>
        <translation>programming</translation>
    </message>
    <message>
        <source>system settings</source>
        <translation>system settings</translation>
    </message>
    <message>
        <source>configuration</source>
        <translation>configuration</translation>
    </message>
    <message>
        <source>PLC</source>
        <translation>PLC</translation>
    </message>
    <message>
        <source>all outputs</source>
        <translation>all outputs</translation>
    </message>
    <message>
        <source>users</source>
        <translation>users</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>Edited, not yet written to the device.</source>
        <translation>Edited, not yet written to the device.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>User number</source>
        <translation>User number</translation>
    </message>
    <message>
        <source>Rights</source>
        <translation>Rights</translation>
    </message>
</context>
<context>
    <name>cambench::UsersPage</name>
    <message>
        <source>Show numbers</source>
        <translation>Show numbers</translation>
    </message>
    <message>
        <source>May change all outputs</source>
        <translation>May change all outputs</translation>
    </message>
    <message>
        <source>Add user</source>
        <translation>Add user</translation>
    </message>
    <message>
        <source>Remove user</source>
        <translation>Remove user</translation>
    </message>
    <message>
        <source>User numbers are access codes. They stay hidden unless you show them.</source>
        <translation>User numbers are access codes. They stay hidden unless you show them.</translation>
    </message>
    <message>
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>User number:</source>
        <translation>User number:</translation>
    </message>
    <message>
        <source>Rights</source>
        <translation>Rights</translation>
    </message>
    <message>
        <source>Program selection</source>
        <translation>Program selection</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programming</translation>
    </message>
    <message>
        <source>System settings</source>
        <translation>System settings</translation>
    </message>
    <message>
        <source>Device configuration</source>
        <translation>Device configuration</translation>
    </message>
    <message>
        <source>PLC menu</source>
        <translation>PLC menu</translation>
    </message>
    <message>
        <source>All outputs menu</source>
        <translation>All outputs menu</translation>
    </message>
    <message>
        <source>User menu</source>
        <translation>User menu</translation>
    </message>
    <message>
        <source>Outputs this user may change</source>
        <translation>Outputs this user may change</translation>
    </message>
    <message>
        <source>New user</source>
        <translation>New user</translation>
    </message>
    <message>
        <source>hidden – check &quot;Show numbers&quot; to see or change it</source>
        <translation>hidden – check &quot;Show numbers&quot; to see or change it</translation>
    </message>
    <message>
        <source>Reading users…</source>
        <translation>Reading users…</translation>
    </message>
    <message>
        <source>Reading users failed: %1</source>
        <translation>Reading users failed: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n user(s) read.</source>
        <translation>
            <numerusform>%n user read.</numerusform>
            <numerusform>%n users read.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, number %2, rights: %3</source>
        <translation>%1, number %2, rights: %3</translation>
    </message>
    <message>
        <source>absent</source>
        <translation>absent</translation>
    </message>
    <message>
        <source>User &quot;%1&quot;</source>
        <translation>User &quot;%1&quot;</translation>
    </message>
    <message>
        <source>deleted</source>
        <translation>deleted</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Users</translation>
    </message>
</context>
<context>
    <name>cambench::comm</name>
    <message>
        <source>baud rate %1 is not a positive number</source>
        <translation>baud rate %1 is not a positive number</translation>
    </message>
    <message>
        <source>%1 data bits: use 5, 6, 7 or 8</source>
        <translation>%1 data bits: use 5, 6, 7 or 8</translation>
    </message>
    <message>
        <source>parity &apos;%1&apos;: use N, E, O, S or M</source>
        <translation>parity &apos;%1&apos;: use N, E, O, S or M</translation>
    </message>
    <message>
        <source>%1 stop bits: use 1, 2 or 3 (one and a half)</source>
        <translation>%1 stop bits: use 1, 2 or 3 (one and a half)</translation>
    </message>
    <message>
        <source>flow control &apos;%1&apos;: use N (none), H (RTS/CTS) or S (XON/XOFF)</source>
        <translation>flow control &apos;%1&apos;: use N (none), H (RTS/CTS) or S (XON/XOFF)</translation>
    </message>
    <message>
        <source>cannot use %1: %2</source>
        <translation>cannot use %1: %2</translation>
    </message>
    <message>
        <source>check the port name and that no other program uses it</source>
        <translation>check the port name and that no other program uses it</translation>
    </message>
    <message>
        <source>check the port name and that the adapter is plugged in</source>
        <translation>check the port name and that the adapter is plugged in</translation>
    </message>
    <message>
        <source>cannot open %1: %2; %3</source>
        <translation>cannot open %1: %2; %3</translation>
    </message>
    <message>
        <source>the port %1 disappeared (cable pulled or adapter removed); reconnect and retry</source>
        <translation>the port %1 disappeared (cable pulled or adapter removed); reconnect and retry</translation>
    </message>
    <message>
        <source>%1 %2 failed: %3; reconnect and retry</source>
        <translation>%1 %2 failed: %3; reconnect and retry</translation>
    </message>
    <message>
        <source>the port %1 is not open; connect first</source>
        <translation>the port %1 is not open; connect first</translation>
    </message>
    <message>
        <source>could not send %1 bytes to %2 within %3 ms; check the flow control setting (RTS/CTS needs the CTS line)</source>
        <translation>could not send %1 bytes to %2 within %3 ms; check the flow control setting (RTS/CTS needs the CTS line)</translation>
    </message>
    <message>
        <source>reading from</source>
        <translation>reading from</translation>
    </message>
    <message>
        <source>no answer within %1 ms</source>
        <translation>no answer within %1 ms</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2; check the address, the port and that the device server is switched on</source>
        <translation>cannot connect to %1: %2; check the address, the port and that the device server is switched on</translation>
    </message>
    <message>
        <source>the device server %1 closed the connection; reconnect and retry</source>
        <translation>the device server %1 closed the connection; reconnect and retry</translation>
    </message>
    <message>
        <source>the connection to %1 failed: %2; reconnect and retry</source>
        <translation>the connection to %1 failed: %2; reconnect and retry</translation>
    </message>
    <message>
        <source>not connected to %1; connect first</source>
        <translation>not connected to %1; connect first</translation>
    </message>
    <message>
        <source>could not send %1 bytes to %2 within %3 ms; check the network</source>
        <translation>could not send %1 bytes to %2 within %3 ms; check the network</translation>
    </message>
    <message>
        <source>write it as tcp://host:port, e.g. tcp://10.0.0.5:4001</source>
        <translation>write it as tcp://host:port, e.g. tcp://10.0.0.5:4001</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no host; %2</source>
        <translation>&apos;%1&apos; names no host; %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no TCP port (1..65535); %2</source>
        <translation>&apos;%1&apos; names no TCP port (1..65535); %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has more than a host and a port; %2</source>
        <translation>&apos;%1&apos; has more than a host and a port; %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: unknown scheme; use tcp://host:port, a serial port name or sim</source>
        <translation>&apos;%1&apos;: unknown scheme; use tcp://host:port, a serial port name or sim</translation>
    </message>
    <message>
        <source>no port given; name a serial port (/dev/ttyUSB0, COM3), tcp://host:port or sim</source>
        <translation>no port given; name a serial port (/dev/ttyUSB0, COM3), tcp://host:port or sim</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no port this program can open</source>
        <translation>&apos;%1&apos; names no port this program can open</translation>
    </message>
    <message>
        <source>the request could not be sent</source>
        <translation>the request could not be sent</translation>
    </message>
    <message>
        <source>no reply, though the device answered %1</source>
        <translation>no reply, though the device answered %1</translation>
    </message>
    <message>
        <source>no valid reply (last: %1)</source>
        <translation>no valid reply (last: %1)</translation>
    </message>
    <message>
        <source>not connected to a device; connect first</source>
        <translation>not connected to a device; connect first</translation>
    </message>
    <message>
        <source>the connection %1 closed; reconnect and retry</source>
        <translation>the connection %1 closed; reconnect and retry</translation>
    </message>
    <message>
        <source>not connected: connecting to %1</source>
        <translation>not connected: connecting to %1</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;; known: %2</source>
        <translation>unknown protocol &quot;%1&quot;; known: %2</translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation>not connected: %1</translation>
    </message>
    <message>
        <source>Users and rights exist only in %1.</source>
        <translation>Users and rights exist only in %1.</translation>
    </message>
    <message>
        <source>EEPROM backup and restore exist only in %1.</source>
        <translation>EEPROM backup and restore exist only in %1.</translation>
    </message>
    <message>
        <source>Typed requests exist only in %1.</source>
        <translation>Typed requests exist only in %1.</translation>
    </message>
    <message>
        <source>Output and program names exist only in %1.</source>
        <translation>Output and program names exist only in %1.</translation>
    </message>
    <message>
        <source>This protocol does not reach the PLC logic module.</source>
        <translation>This protocol does not reach the PLC logic module.</translation>
    </message>
    <message>
        <source>Dead-time modes exist only in %1.</source>
        <translation>Dead-time modes exist only in %1.</translation>
    </message>
    <message>
        <source>Analogue cams exist only in %1.</source>
        <translation>Analogue cams exist only in %1.</translation>
    </message>
    <message>
        <source>The EEPROM lock exists only in %1.</source>
        <translation>The EEPROM lock exists only in %1.</translation>
    </message>
    <message>
        <source>bytes outside any frame</source>
        <translation>bytes outside any frame</translation>
    </message>
    <message>
        <source>a frame ended by CR without LF</source>
        <translation>a frame ended by CR without LF</translation>
    </message>
    <message>
        <source>No frame end within %1 bytes; the frame was dropped.</source>
        <translation>No frame end within %1 bytes; the frame was dropped.</translation>
    </message>
    <message>
        <source>the rest of an oversized frame</source>
        <translation>the rest of an oversized frame</translation>
    </message>
    <message>
        <source>The frame has no checksum characters.</source>
        <translation>The frame has no checksum characters.</translation>
    </message>
    <message>
        <source>Checksum %1 received, %2 expected.</source>
        <translation>Checksum %1 received, %2 expected.</translation>
    </message>
    <message>
        <source>Skipped %1 bytes: %2.</source>
        <translation>Skipped %1 bytes: %2.</translation>
    </message>
    <message>
        <source>The value %1 of field &quot;%2&quot; is outside %3..%4 (%5 hex digits); use a value in that range.</source>
        <translation>The value %1 of field &quot;%2&quot; is outside %3..%4 (%5 hex digits); use a value in that range.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; needs a number, got &quot;%2&quot;.</source>
        <translation>Field &quot;%1&quot; needs a number, got &quot;%2&quot;.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; contains a NUL character; remove it.</source>
        <translation>Field &quot;%1&quot; contains a NUL character; remove it.</translation>
    </message>
    <message>
        <source>The text &quot;%1&quot; of field &quot;%2&quot; is %3 characters long; at most %4 fit.</source>
        <translation>The text &quot;%1&quot; of field &quot;%2&quot; is %3 characters long; at most %4 fit.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; needs exactly %2 bytes, got %3.</source>
        <translation>Field &quot;%1&quot; needs exactly %2 bytes, got %3.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; needs exactly %2 words, got %3.</source>
        <translation>Field &quot;%1&quot; needs exactly %2 words, got %3.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; has an unknown type.</source>
        <translation>Field &quot;%1&quot; has an unknown type.</translation>
    </message>
    <message>
        <source>Malformed data: field &quot;%1&quot; at offset %2 %3.</source>
        <translation>Malformed data: field &quot;%1&quot; at offset %2 %3.</translation>
    </message>
    <message>
        <source>has %1 characters, not a multiple of %2</source>
        <translation>has %1 characters, not a multiple of %2</translation>
    </message>
    <message>
        <source>is not hexadecimal</source>
        <translation>is not hexadecimal</translation>
    </message>
    <message>
        <source>has an odd number of digits</source>
        <translation>has an odd number of digits</translation>
    </message>
    <message>
        <source>%1: expected &quot;OK&quot;, got &quot;%2&quot;.</source>
        <translation>%1: expected &quot;OK&quot;, got &quot;%2&quot;.</translation>
    </message>
    <message>
        <source>needs %1 characters, only %2 left</source>
        <translation>needs %1 characters, only %2 left</translation>
    </message>
    <message>
        <source>Malformed data: %1 unexpected characters after the last field.</source>
        <translation>Malformed data: %1 unexpected characters after the last field.</translation>
    </message>
    <message>
        <source>Cannot send %1: %2</source>
        <translation>Cannot send %1: %2</translation>
    </message>
    <message>
        <source>The request does not start with %1.</source>
        <translation>The request does not start with %1.</translation>
    </message>
    <message>
        <source>%1 has no data reply.</source>
        <translation>%1 has no data reply.</translation>
    </message>
    <message>
        <source>Cannot answer %1: %2</source>
        <translation>Cannot answer %1: %2</translation>
    </message>
    <message>
        <source>the device</source>
        <translation>the device</translation>
    </message>
    <message>
        <source>check the cable, the baud rate, that the device speaks the Multiuser protocol and the device number</source>
        <translation>check the cable, the baud rate, that the device speaks the Multiuser protocol and the device number</translation>
    </message>
    <message>
        <source>check the cable, the baud rate and that the device speaks the Standard protocol</source>
        <translation>check the cable, the baud rate and that the device speaks the Standard protocol</translation>
    </message>
    <message>
        <source>a reply with a wrong checksum</source>
        <translation>a reply with a wrong checksum</translation>
    </message>
    <message>
        <source>an oversized reply</source>
        <translation>an oversized reply</translation>
    </message>
    <message>
        <source>a malformed reply: %1</source>
        <translation>a malformed reply: %1</translation>
    </message>
    <message>
        <source>the device repeated an answer to an earlier request</source>
        <translation>the device repeated an answer to an earlier request</translation>
    </message>
    <message>
        <source>%1 is not a command of the catalogue</source>
        <translation>%1 is not a command of the catalogue</translation>
    </message>
    <message>
        <source>%1: the device reported error %2: %3</source>
        <translation>%1: the device reported error %2: %3</translation>
    </message>
    <message>
        <source>%1: the device does not know this command (firmware dated %2); it needs a newer firmware for it</source>
        <translation>%1: the device does not know this command (firmware dated %2); it needs a newer firmware for it</translation>
    </message>
    <message>
        <source>a request starts with &apos;?&apos; or &apos;!&apos;, not &apos;%1&apos;</source>
        <translation>a request starts with &apos;?&apos; or &apos;!&apos;, not &apos;%1&apos;</translation>
    </message>
    <message>
        <source>an empty request: type the command letters after %1</source>
        <translation>an empty request: type the command letters after %1</translation>
    </message>
    <message>
        <source>an empty request: type ? or ! and the command</source>
        <translation>an empty request: type ? or ! and the command</translation>
    </message>
    <message>
        <source>CamCon ASCII, Multiuser (RS485 bus)</source>
        <translation>CamCon ASCII, Multiuser (RS485 bus)</translation>
    </message>
    <message>
        <source>CamCon ASCII, Standard (RS232)</source>
        <translation>CamCon ASCII, Standard (RS232)</translation>
    </message>
    <message>
        <source>the %1 protocol got settings of %2</source>
        <translation>the %1 protocol got settings of %2</translation>
    </message>
    <message>
        <source>another protocol</source>
        <translation>another protocol</translation>
    </message>
    <message>
        <source>reading the device identity (?EPROM)</source>
        <translation>reading the device identity (?EPROM)</translation>
    </message>
    <message>
        <source>reading the device identity (?%1)</source>
        <translation>reading the device identity (?%1)</translation>
    </message>
    <message>
        <source>reading the error state (?ERR)</source>
        <translation>reading the error state (?ERR)</translation>
    </message>
    <message>
        <source>reading the status (?%1)</source>
        <translation>reading the status (?%1)</translation>
    </message>
    <message>
        <source>resetting the error (!ERR)</source>
        <translation>resetting the error (!ERR)</translation>
    </message>
    <message>
        <source>selecting program %1 (!PAU)</source>
        <translation>selecting program %1 (!PAU)</translation>
    </message>
    <message>
        <source>program %1, output %2</source>
        <translation>program %1, output %2</translation>
    </message>
    <message>
        <source>reading %1: the device reports more than %2 cams on one track; check the device</source>
        <translation>reading %1: the device reports more than %2 cams on one track; check the device</translation>
    </message>
    <message>
        <source>inserting the cam %1..%2 on %3 (!NINS)</source>
        <translation>inserting the cam %1..%2 on %3 (!NINS)</translation>
    </message>
    <message>
        <source> On an insert the usual cause is a cam that overlaps another cam of the track or lies outside the device&apos;s range.</source>
        <translation> On an insert the usual cause is a cam that overlaps another cam of the track or lies outside the device&apos;s range.</translation>
    </message>
    <message>
        <source>deleting the cam at %1 on %2 (!NDEL)</source>
        <translation>deleting the cam at %1 on %2 (!NDEL)</translation>
    </message>
    <message>
        <source> Nothing had been changed on the track yet.</source>
        <translation> Nothing had been changed on the track yet.</translation>
    </message>
    <message>
        <source> The cams already changed were put back: the track is as it was.</source>
        <translation> The cams already changed were put back: the track is as it was.</translation>
    </message>
    <message>
        <source> Putting the track back failed too: it may now hold other cams than before; read it to see.</source>
        <translation> Putting the track back failed too: it may now hold other cams than before; read it to see.</translation>
    </message>
    <message>
        <source>writing %1: after lost replies the device holds %2 cams instead of the %3 written; write the track again</source>
        <translation>writing %1: after lost replies the device holds %2 cams instead of the %3 written; write the track again</translation>
    </message>
    <message>
        <source>deleting program %1 (!PDEL)</source>
        <translation>deleting program %1 (!PDEL)</translation>
    </message>
    <message>
        <source>copying program %1 to program %2 (!PCPY)</source>
        <translation>copying program %1 to program %2 (!PCPY)</translation>
    </message>
    <message>
        <source>copying output %1 to output %2 in program %3 (!PACPY)</source>
        <translation>copying output %1 to output %2 in program %3 (!PACPY)</translation>
    </message>
    <message>
        <source>reading the dead time of output %1 (?TZK)</source>
        <translation>reading the dead time of output %1 (?TZK)</translation>
    </message>
    <message>
        <source>writing the dead time of output %1 (!TZK)</source>
        <translation>writing the dead time of output %1 (!TZK)</translation>
    </message>
    <message>
        <source>reading the name of output %1 (?ANAME)</source>
        <translation>reading the name of output %1 (?ANAME)</translation>
    </message>
    <message>
        <source>writing the name of output %1 (!ANAME)</source>
        <translation>writing the name of output %1 (!ANAME)</translation>
    </message>
    <message>
        <source>reading the name of program %1 (?PNAME)</source>
        <translation>reading the name of program %1 (?PNAME)</translation>
    </message>
    <message>
        <source>writing the name of program %1 (!PNAME)</source>
        <translation>writing the name of program %1 (!PNAME)</translation>
    </message>
    <message>
        <source>reading the settings (?%1)</source>
        <translation>reading the settings (?%1)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no device setting</source>
        <translation>&quot;%1&quot; is no device setting</translation>
    </message>
    <message>
        <source>reading user entry %1 (?USER)</source>
        <translation>reading user entry %1 (?USER)</translation>
    </message>
    <message>
        <source>reading the users: the device lists more than %1 entries and no end; check the device</source>
        <translation>reading the users: the device lists more than %1 entries and no end; check the device</translation>
    </message>
    <message>
        <source>writing user &quot;%1&quot; (!USER)</source>
        <translation>writing user &quot;%1&quot; (!USER)</translation>
    </message>
    <message>
        <source>deleting a user (!USER)</source>
        <translation>deleting a user (!USER)</translation>
    </message>
    <message>
        <source>reading %1 (?GMXSPS)</source>
        <translation>reading %1 (?GMXSPS)</translation>
    </message>
    <message>
        <source>writing %1 (!GMXSPS)</source>
        <translation>writing %1 (!GMXSPS)</translation>
    </message>
    <message>
        <source>reading the actual value of %1 (?SPSIST)</source>
        <translation>reading the actual value of %1 (?SPSIST)</translation>
    </message>
    <message>
        <source>reading the set value of %1 (?SPSSOLL)</source>
        <translation>reading the set value of %1 (?SPSSOLL)</translation>
    </message>
    <message>
        <source>reading EEPROM block %1 (?EE)</source>
        <translation>reading EEPROM block %1 (?EE)</translation>
    </message>
    <message>
        <source>the device sent no EEPROM block 0000; check the device</source>
        <translation>the device sent no EEPROM block 0000; check the device</translation>
    </message>
    <message>
        <source>asked for EEPROM block %1, the device sent block %2; try again</source>
        <translation>asked for EEPROM block %1, the device sent block %2; try again</translation>
    </message>
    <message>
        <source>the device sent a malformed EEPROM block: %1; try again</source>
        <translation>the device sent a malformed EEPROM block: %1; try again</translation>
    </message>
    <message>
        <source>the device sent EEPROM blocks up to FFFE without the end marker FFFF; check the device</source>
        <translation>the device sent EEPROM blocks up to FFFE without the end marker FFFF; check the device</translation>
    </message>
    <message>
        <source>the EEPROM image does not start with block 0000; nothing was sent</source>
        <translation>the EEPROM image does not start with block 0000; nothing was sent</translation>
    </message>
    <message>
        <source>The device may already be ERASED (block 0000 starts the erase).</source>
        <translation>The device may already be ERASED (block 0000 starts the erase).</translation>
    </message>
    <message>
        <source>The device is now ERASED: it holds only the blocks before %1 and does not run.</source>
        <translation>The device is now ERASED: it holds only the blocks before %1 and does not run.</translation>
    </message>
    <message>
        <source>The device holds every block but did not confirm that it started.</source>
        <translation>The device holds every block but did not confirm that it started.</translation>
    </message>
    <message>
        <source>restore failed at EEPROM block %1 of %2 (!EE%3). %4 Running the same restore again is safe: it starts by erasing the device. Cause</source>
        <translation>restore failed at EEPROM block %1 of %2 (!EE%3). %4 Running the same restore again is safe: it starts by erasing the device. Cause</translation>
    </message>
    <message>
        <source>a bus scan needs the Multiuser protocol; connect with --protocol multiuser</source>
        <translation>a bus scan needs the Multiuser protocol; connect with --protocol multiuser</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>no reply</translation>
    </message>
    <message>
        <source>1 attempt</source>
        <translation>1 attempt</translation>
    </message>
    <message>
        <source>%1 attempts</source>
        <translation>%1 attempts</translation>
    </message>
    <message>
        <source>%1 from %2 to %3 on %4 after %5 of %6 ms; %7</source>
        <translation>%1 from %2 to %3 on %4 after %5 of %6 ms; %7</translation>
    </message>
    <message>
        <source>device %1</source>
        <translation>device %1</translation>
    </message>
    <message>
        <source>reading %1 (?NF)</source>
        <translation>reading %1 (?NF)</translation>
    </message>
    <message>
        <source>reading %1 (?NN)</source>
        <translation>reading %1 (?NN)</translation>
    </message>
    <message>
        <source>reading %1 (?NS)</source>
        <translation>reading %1 (?NS)</translation>
    </message>
    <message>
        <source>reading %1 (?%2)</source>
        <translation>reading %1 (?%2)</translation>
    </message>
    <message>
        <source>writing %1 (!%2)</source>
        <translation>writing %1 (!%2)</translation>
    </message>
    <message>
        <source>Editing a program other than the active one exists only in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a reply without a frame start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a reply that broke off before its end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restore: the device took every block but did not confirm that it started (!EE%1): %2. Run the same restore again. Cause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the end block, sent again, failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the EEPROM back failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its EEPROM differs from the image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 blocks read back, %2 in the image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead-time modes are data words 251..253, which 3964R e38 cannot address (words 0..127); set the device to 3964R n96 (--protocol 3964r-n96) to reach them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connection speaks %1, which does not reach this kind of device; connect with a protocol of its family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512 read of data area %1 at offset %2 (%3 16-bit words)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512 write of data area %1 at offset %2 (%3 16-bit words)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error 16, command unknown: the device serves only data blocks (&apos;D&apos;). The tool sent another block type; report this as a bug.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error 20, beyond the data block: the words asked for reach past the end of the data area, or the area does not exist on this device or firmware. Check the area and word numbers against the device&apos;s manual.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error 22, command unknown: the device knows only read (&apos;E&apos;) and write (&apos;A&apos;). The tool sent another order; report this as a bug.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error 52, too many data: more than 128 bytes (64 16-bit words) in one telegram. Split the transfer into smaller telegrams.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error 54, general error: the device refused the request, e.g. a write to a read-only word, a value out of range, or the EEPROM busy. Check the value and whether the word may be written, then try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error %1, not listed in the manual: the device refused the request for a reason the tool does not know. Check the request and the device&apos;s display.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512: data area %1 does not exist (1..255).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512: offset %1 does not fit in the offset byte (0..255); split the transfer or use 3964R n96.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512: %1 16-bit words in one telegram (%2..%3 allowed); split the transfer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 carries %2 data bytes, %3 expected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the reply is no RK512 reply (it must start with 00 00 00, got %2). Check that the device&apos;s serial mode is 3964R n96 or e38.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the reply carries %2 data bytes, %3 expected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512: %1 data bytes do not make whole 32-bit table words.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table transfer: data area %1 does not exist (1..255).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table transfer of %1 words from data area %2: nothing to transfer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table transfer: %1 words per telegram (1..%2 allowed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table transfer: words %1..%2 of data area %3 are outside the words 0..%4 that %5 can address.%6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Switch the device to 3964R n96 to reach them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam %1 (%2..%3): 0x80000000 marks an empty cam on the device and cannot be a switch point; move the point by one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam %1 switches on and off at %2: the device would delete it. Give it a length or remove it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam %1 does not exist (1..%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A track holds at most %1 cams; this one has %2. Remove %3 cams.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track words must come in on/off pairs, at most %1; got %2 words.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam %1 reads %2..%3, which is no cam: the device&apos;s track data are inconsistent. Read the track again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>status query 0x01</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error reset 0x02</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program change 0x03</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>track read 0x04</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>track write 0x05</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dead-time read 0x06</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dead-time write 0x07</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>short command 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cause of the error is still present; check the encoder and the outputs, then reset again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check that the program number is within the device&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the program and output numbers, that the cams lie between the smallest and largest actual value, and that the device has room for them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the output number and that the dead time does not exceed the device&apos;s largest dead time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 does not fit the byte of the short command (%3..255).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 does not fit the 16-bit word of the short command (0..65535).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device does not know the %1 (it answered &quot;:Z&quot;); its firmware may not have it. Use the table interface (RK512) instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The reply to the %1 does not start with &apos;:&apos; and its number (got %2). Check that the device&apos;s serial mode is 3964R.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The reply to the %1 has %2 bytes, %3 expected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 does not fit the 16-bit word of the short commands (%3..%4); use the table interface (RK512).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Virtual inputs go in whole 16-bit words; give a multiple of 16 (got %1). Choose the extra bits with care: without the PLC logic module a 0 switches its output off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 virtual inputs do not fit one status query (at most %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished">Output</translation>
    </message>
    <message>
        <source>Cam count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1, cam %2: switch-on point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1, cam %2: switch-off point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The track write needs %1 bytes; a short command holds %2 (about 14 cams in all). Write fewer tracks per command, or use the table interface (RK512) for longer tracks.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead time (0.1 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>actual-value error %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown status %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at least %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 for %2 outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device refused the %1 (it answered &quot;ER&quot;). %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The reply to the %1 is neither &quot;OK&quot; nor &quot;ER&quot; (got %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Asked for program %1, output %2; the reply is for program %3, output %4. Read the track again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 for %2 cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Asked for the dead time of output %1; the reply is for output %2. Read it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished">Speed</translation>
    </message>
    <message>
        <source>Output count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 outputs do not fit one status reply.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch-on point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch-off point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cams do not fit one track reply (at most 14).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check the cable, that the device&apos;s serial mode (menu &quot;Ser:&quot;) is %1 and the line %2 8%3%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a telegram before the device took the request</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R handshake, or a block answered with NAK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512 read of area %1, offset %2 (1 word)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512 write of area %1, offset %2 (1 word)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512 read of area %1, offset %2 (%3 words)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RK512 write of area %1, offset %2 (%3 words)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a telegram that is no RK512 reply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an RK512 reply of %1 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: empty telegram</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a telegram that answers another command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output %1 does not exist in the table interface (outputs %2..%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the device identity (data area %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the actual value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the status (0x01)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>resetting the error (0x02)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>selecting program %1 (0x03)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>selecting program %1 for programming (data area %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device reports %1 %2, which no track holds (0..%3); check the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device reports %1 %2 but its places hold %3; read again, and check the device if this persists</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all %1 places that %2 reaches hold %3, so there may be more; read them over 3964R n96 (--protocol 3964r-n96)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device may still hold the old %1 or already the first of the new ones; read it to see, or write it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device now holds only the first %1 of the %2 %3 written (the old ones are gone); write it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading program %1</source>
        <translation type="unfinished">reading program %1</translation>
    </message>
    <message>
        <source>writing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 cams, but over %3 a track can hold at most %4 (the places it reaches); use 3964R n96 (--protocol 3964r-n96)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deleting program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>copying program %1 to program %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the dead time of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the dead time of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the dead-time mode of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the device reports mode %2, which the manual does not list (0, 1, 2); check the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the dead-time mode of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the settings (data area %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (device value %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (no data word in the table interface)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (a value the settings cannot show)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameters of special encoder types other than the selected type %1 (the device keeps only those of one type)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be written over the table interface (no data word); leave them out. Nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the special encoder of type %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the settings (data area %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the device holds %2, which the settings cannot show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the device&apos;s special encoder is of type %2, and it keeps the parameters of that type only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no setting the table interface has a data word for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 does not exist (areas O, P, M, X; numbers from 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the actual value of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the set value of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the analogue cams of analogue output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: analogue outputs are 1..%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>base points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the analogue cams of analogue output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 base points, but over %3 at most %4 fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>locking the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unlocking the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon table interface, %1 (%2 8%3%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 protocol got settings of another protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R: a telegram is still being sent; wait for its end before sending the next one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R: a telegram of %1 bytes cannot be sent (1..%2 bytes allowed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no DLE within %1 ms after STX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no DLE within %1 ms after the block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 instead of DLE after STX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NAK after the block (the partner found it bad)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STX instead of DLE after the block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 instead of DLE after the block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R: %1; the device may have executed the telegram, which must not be sent twice. Read back what it changes before trying again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R: the partner did not acknowledge the telegram in %1 attempts (last: %2). Check the cable and that the device&apos;s serial mode is 3964R with the same baud rate and parity (n96: 9600 8N1, e38: 38400 8E1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>permission denied on %1 (%2): this user may not open the serial port, or another program holds it. On Linux, add the user to the group dialout (sudo usermod -aG dialout $USER), then log out and in again; close any other program that uses the port.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The short commands of the S7-CP340 coupling exist only in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the end of the list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the start of the list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>user &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>between %1 and %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>and %1 more places</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the users: the list changed while it was read (near %1); nothing is shown; read it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the users: after %1 walks through the list, %2 users were seen but one may still be missing %3; the list may be incomplete, so none is shown; check the cable and try again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading output %1 of program %2 (0x04)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing output %1 of program %2 (0x05)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the dead time of output %1 (0x06)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing the dead time of output %1 (0x07)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the CamCon ASCII protocol (Standard or Multiuser)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the CamCon table interface (3964R n96 or e38)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon, EPROM %1, device %2, %3 outputs, %4 programs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this protocol has no bus to scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check the cable (MC100: RxD/TxD crossed; MC200: 1:1, and DTR high, RTS low power its interface), the baud rate (MC100: 9600) and the controller&apos;s variant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC program present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC program running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error: invalid opcode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error: stack overflow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>breakpoint list cleared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>task switching off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>current bit result 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC program at a breakpoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no PLC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running, PC %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped, PC %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start the PLC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop the PLC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>run one step of the PLC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reset the controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>save to flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>load from flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1 is moving to %2 (now at %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1 stands at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, axis error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home axis %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move axis %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move axis %1 by %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move axis %1 continuously in the plus direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move axis %1 continuously in the minus direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop axis %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop axis %1 with the maximum ramp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acknowledge the error of axis %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>set the speed of axis %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no MC100/MC200 answers reading variable 1: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>probed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connection is set to the %1, but the controller answers as an %2 (variables of %3 bits): choose %2 or automatic detection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as given, confirmed by the probe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as given (the probe found the %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 cannot %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the memory telegrams need an MC200</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this needs an MC200 V2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished">%1 (%2)</translation>
    </message>
    <message>
        <source>PLC program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>variable numbers are 0 to 65535, not %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V%1 of the %2 holds %3 to %4 (%5 bits), not %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is an input: inputs are read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading it failed too: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished">%1 %2</translation>
    </message>
    <message>
        <source>set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the answer to &quot;%1&quot; was lost (%2); it was not sent again, because it acts each time it arrives. Read back: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>report its program status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the status failed too: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>report its axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axes are %1 to %2, not %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a speed must be more than 0, not %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the move may have started: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the axis failed too: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>memory is 0x0000 to 0xFFFF: %1 bytes from 0x%2 do not fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>write memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC-1 (RS232)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no 0xFF synchronisation byte from the MC100MA for %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC100 ASCII (RS232)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the MC100 (ASCII protocol)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check the cable (RxD/TxD crossed), 9600 baud, and that the MC100 speaks ASCII (a controller set to the binary protocol answers only that: connect with mc1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ASCII protocol, which looks alike on V1 and V2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no MC100 answers in ASCII reading V1: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC100 (ASCII protocol)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V%1 of the MC100 holds %2 to %3 (24 bits), not %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>external RAM page %1 (only the flags&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the MC100&apos;s ASCII protocol has no requests for %1; an MC200 V2 over the binary protocol (mc1) has</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the program status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the answer &quot;%1&quot; holds a byte that is no printable ASCII (0x%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the answer &quot;%1&quot; is no error number (! and four hex digits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the answer is an empty line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive refused %1 with %2 (an error number CamBench does not know: see the drive&apos;s manual)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive refused %1 with %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Compax3 (RS232)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Compax3 at address %1 (RS485)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check the cable (a null-modem cable with RTS/CTS), the baud rate (115200 unless set otherwise in the C3 ServoManager) and that the drive is powered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check the RS485 wiring, the baud rate and the drive&apos;s address (C3 ServoManager, &quot;RS485 settings&quot;); `c3 scan` lists the addresses that answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>input I%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position reached</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>powerless</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>powered standstill</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zero known</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PSB0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PSB1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PSB2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>motor temperature (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>following error (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end limit + (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end limit − (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>direction change while moving (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error %1 (%2): see the drive&apos;s manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>powerless at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>moving, now at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>power the axis and acknowledge errors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switch the axis powerless</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jog the axis in + direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jog the axis in − direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acceleration %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start homing (set 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start set %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 answered %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>what answers is no Compax3: its info string is &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, serial number %2%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 answered %2 with &quot;&gt;&quot;, not a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 answered %2 with &quot;%3&quot;, not &quot;&gt;&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 answered O%2 with &quot;%3&quot;, not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the answer to &quot;%1&quot; was lost (%2); it was not sent again, because it moves the axis each time it arrives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. Reading back failed too (%2): the axis&apos;s state is unknown; look at the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the command was taken</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the command was not taken (control word %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. Read back: %2; the axis is %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the set must be 0 to %1, not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the axis is powerless: enable it first (nothing was sent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compax3 ASCII (RS485)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compax3 ASCII (RS232)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>powered, standing at %1 (last set %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no Compax3 answered at any RS485 address 0..99</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sending a break on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A bus scan needs the Multiuser or the Cam-BUS protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Cam-BUS block holds 1 to 255 bytes, not %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Cam-BUS block with LEN 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Cam-BUS block whose checksum is %1, not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Cam-BUS block of %1 bytes holds no CamCon frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Cam-BUS block that does not start with ?, ! or : (0x%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a frame in a Cam-BUS block with checksum %1, not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>user %1 did not acknowledge the block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an initialisation phase began before user %1 acknowledged the block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>user %1 did not answer its TO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam-BUS device %1 (PC %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check that device %1 is on the Cam-BUS (scan lists its users), the RS485 wiring and 38400 baud, and that no other user has the PC&apos;s number %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs %2 bytes, more than a Cam-BUS block holds (255)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no Cam-BUS traffic: no user passed the token in %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PC (user %1) got no turn on the Cam-BUS in %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>device %1 did not take the request in %2 turns (%3); it was not executed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the request went to device %1 but was not acknowledged (%2); it may have been executed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Cam-BUS: users %1 get the token; which of them are CamCons, a scan tells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no Cam-BUS token heard in %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no Cam-BUS traffic in %1 s on %2: no user passes the token; %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon Cam-BUS (RS485 token bus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PC could not join the Cam-BUS: after %1 initialisation phases the master still passes user %2 no token (its answers may come too late for the bus: a USB adapter&apos;s latency timer should be 1 ms; or another user has number %2); the request was not sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>device %1&apos;s receive queue stayed full for %2 s (it refused the request %3 times); the request was not sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not sent: dropped by STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the number of analogue outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device says it has %1 analogue outputs (area 203 word 38); the manual allows 0..%2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench&apos;s built-in guess (comm/mc1/README.md), not the controller&apos;s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected name,axis,parameter (3 fields), found %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the name must be position, target or status, not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the axis must be %1 to %2, not &quot;%3&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameter must be 0 to 65535 (or 0x0000 to 0xFFFF), not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 of axis %2 is named a second time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no name,axis,parameter line: the file holds no parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (provisional parameter numbers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axes are numbers %1 to %2 separated by commas (1,2,5); &quot;%3&quot; is not one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no axis given: name them like 1,2,5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none: the %1 has no axis telegrams (they need an MC200 V2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>found with RDTABLE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameter table (%1) names no %2 parameter for axis %3: load a table that names it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller refused RDSTAT of parameter %1 (0x%2), the %3 of axis %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: that number is CamBench&apos;s guess, not the controller&apos;s; load the controller&apos;s parameter table (name,axis,parameter; --parameters FILE, or Load parameter table… on the Axes page)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: check the parameter table %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller has no axis %1: its axes are %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished">none</translation>
    </message>
    <message>
        <source>no answer to &quot;%1&quot; (%2). Read back: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the axis back failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not acknowledged: %1; %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller has no axes (%1): nothing to stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1 moves (provisional parameter numbers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1 moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none: the MC100&apos;s ASCII protocol has no axis requests</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>absolute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>relative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mode %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the state could not be read back afterwards: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive is powered already: nothing was sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive is powered with an error pending (%1): nothing was sent, because acknowledging it drops power; stop the axis, Disable, then Enable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compax3 drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compax3 drive at address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped before it moved: %1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is running on this device: motion is not queued (it would start by itself when that ends); ask again then</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>; the PC was too late to answer on the bus %n time(s) during this request (the bus waits %1 ms for an answer: a USB adapter&apos;s latency timer should be 1 ms, and a computer this busy is too slow for the bus)</source>
        <translation>
            <numerusform>; the PC was too late to answer on the bus %n time during this request (the bus waits %1 ms for an answer: a USB adapter&apos;s latency timer should be 1 ms, and a computer this busy is too slow for the bus)</numerusform>
            <numerusform>; the PC was too late to answer on the bus %n times during this request (the bus waits %1 ms for an answer: a USB adapter&apos;s latency timer should be 1 ms, and a computer this busy is too slow for the bus)</numerusform>
        </translation>
    </message>
    <message>
        <source>no such axis: the controller refused its stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>could not tell whether axis %1 moves: its status was read through CamBench&apos;s guessed parameter numbers (provisional), not the controller&apos;s; load the controller&apos;s parameter table%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (besides: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mode %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deceleration %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>set %1 changed on the drive since it was read at %2 (%3): nothing was sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the axis moves (%2, as read through provisional object numbers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the axis is powered (as read through provisional object numbers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 reads as %2, but through the status word 1000.3, whose number and bits are provisional (a public client&apos;s, not Parker&apos;s manual&apos;s): whether the axis stands cannot be told from it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive&apos;s status could not be read (%1), so the axis was stopped by switching its power off (1100.3 = $0000), the one stop that can never power the drive; acknowledged by the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not powered: nothing to stop (nothing was sent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device number:</source>
        <translation type="unfinished">Device number:</translation>
    </message>
    <message>
        <source>the number of the CamCon to talk to on the bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PC number:</source>
        <translation type="unfinished">PC number:</translation>
    </message>
    <message>
        <source>this PC&apos;s own number on the bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiuser (RS485 bus)</source>
        <translation type="unfinished">Multiuser (RS485 bus)</translation>
    </message>
    <message>
        <source>Standard (point to point)</source>
        <translation type="unfinished">Standard (point to point)</translation>
    </message>
    <message>
        <source>Table interface, 3964R n96 (9600 8N1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table interface, 3964R e38 (38400 8E1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam-BUS (RS485 token bus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this PC&apos;s own number on the Cam-BUS, usually 63; no other user of the bus (CamCon, display, another PC) may have it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller variant to expect; auto (the default) probes and names what it found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RS485, 115200 8N1 unless set otherwise in the drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RS232, 115200 8N1 with RTS/CTS unless set otherwise in the drive; a null-modem cable with RTS/CTS.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive&apos;s RS485 address (C3 ServoManager, &quot;RS485 settings&quot;); Scan bus lists the addresses that answer</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::model</name>
    <message>
        <source>a text is expected</source>
        <translation>a text is expected</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has %2 characters; at most %3 are allowed</source>
        <translation>&quot;%1&quot; has %2 characters; at most %3 are allowed</translation>
    </message>
    <message>
        <source>&quot;%1&quot; contains a character the device cannot store (only printable Latin-1 characters are allowed)</source>
        <translation>&quot;%1&quot; contains a character the device cannot store (only printable Latin-1 characters are allowed)</translation>
    </message>
    <message>
        <source>%1 is not one of the allowed values %2</source>
        <translation>%1 is not one of the allowed values %2</translation>
    </message>
    <message>
        <source>0 is not allowed; allowed are %1..-%3 and %3..%2</source>
        <translation>0 is not allowed; allowed are %1..-%3 and %3..%2</translation>
    </message>
    <message>
        <source>%1 is outside the allowed range %2%3</source>
        <translation>%1 is outside the allowed range %2%3</translation>
    </message>
    <message>
        <source>%1 is not a multiple of %2 (allowed are %3 in steps of %2)</source>
        <translation>%1 is not a multiple of %2 (allowed are %3 in steps of %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a whole number</source>
        <translation>&quot;%1&quot; is not a whole number</translation>
    </message>
    <message>
        <source>%1: there is no such setting.</source>
        <translation>%1: there is no such setting.</translation>
    </message>
    <message>
        <source>Could not write %1: %2. The file was not changed.</source>
        <translation>Could not write %1: %2. The file was not changed.</translation>
    </message>
    <message>
        <source>Could not read %1: the file does not exist.</source>
        <translation>Could not read %1: the file does not exist.</translation>
    </message>
    <message>
        <source>Could not read %1: it is not a regular file.</source>
        <translation>Could not read %1: it is not a regular file.</translation>
    </message>
    <message>
        <source>Could not read %1: %2.</source>
        <translation>Could not read %1: %2.</translation>
    </message>
    <message>
        <source>Could not read %1: it is larger than %2 bytes, so it is not a CamBench file.</source>
        <translation>Could not read %1: it is larger than %2 bytes, so it is not a CamBench file.</translation>
    </message>
    <message>
        <source>%1 %2 is below the minimum %3</source>
        <translation>%1 %2 is below the minimum %3</translation>
    </message>
    <message>
        <source>%1 %2 is above the maximum %3</source>
        <translation>%1 %2 is above the maximum %3</translation>
    </message>
    <message>
        <source>switch-on and switch-off point are both %1, so the cam would never switch</source>
        <translation>switch-on and switch-off point are both %1, so the cam would never switch</translation>
    </message>
    <message>
        <source>switch-off point %1 is below the switch-on point %2; only on a rotary axis may a cam wrap through zero</source>
        <translation>switch-off point %1 is below the switch-on point %2; only on a rotary axis may a cam wrap through zero</translation>
    </message>
    <message>
        <source>the device has outputs 1..%1</source>
        <translation>the device has outputs 1..%1</translation>
    </message>
    <message>
        <source>%1 cams, but a track holds at most %2</source>
        <translation>%1 cams, but a track holds at most %2</translation>
    </message>
    <message>
        <source>%1 overlaps cam %2 (%3)</source>
        <translation>%1 overlaps cam %2 (%3)</translation>
    </message>
    <message>
        <source>the device has programs 0..%1</source>
        <translation>the device has programs 0..%1</translation>
    </message>
    <message>
        <source>the track stored for output %1 says it is output %2</source>
        <translation>the track stored for output %1 says it is output %2</translation>
    </message>
    <message>
        <source>%1 has %2 characters; the device stores at most %3</source>
        <translation>%1 has %2 characters; the device stores at most %3</translation>
    </message>
    <message>
        <source>%1 contains &apos;%2&apos;, which the device cannot show (only Latin-1 characters are possible)</source>
        <translation>%1 contains &apos;%2&apos;, which the device cannot show (only Latin-1 characters are possible)</translation>
    </message>
    <message>
        <source>%1 contains the control character 0x%2</source>
        <translation>%1 contains the control character 0x%2</translation>
    </message>
    <message>
        <source>Dead time of output %1: the device compensates outputs 1..%2 only.</source>
        <translation>Dead time of output %1: the device compensates outputs 1..%2 only.</translation>
    </message>
    <message>
        <source>Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).</source>
        <translation>Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).</translation>
    </message>
    <message>
        <source>Name of output %1: the device has outputs 1..%2.</source>
        <translation>Name of output %1: the device has outputs 1..%2.</translation>
    </message>
    <message>
        <source>Name of output %1: %2.</source>
        <translation>Name of output %1: %2.</translation>
    </message>
    <message>
        <source>Name of program %1: the device has programs 0..%2.</source>
        <translation>Name of program %1: the device has programs 0..%2.</translation>
    </message>
    <message>
        <source>Name of program %1: %2.</source>
        <translation>Name of program %1: %2.</translation>
    </message>
    <message>
        <source>the name %1</source>
        <translation>the name %1</translation>
    </message>
    <message>
        <source>the user number must have 1 to %1 characters</source>
        <translation>the user number must have 1 to %1 characters</translation>
    </message>
    <message>
        <source>the user number may hold only printable ASCII characters</source>
        <translation>the user number may hold only printable ASCII characters</translation>
    </message>
    <message>
        <source>the user number &quot;DEL&quot; is reserved: it deletes a user</source>
        <translation>the user number &quot;DEL&quot; is reserved: it deletes a user</translation>
    </message>
    <message>
        <source>%1 output access entries, but the device has %2</source>
        <translation>%1 output access entries, but the device has %2</translation>
    </message>
    <message>
        <source>%1 has the same user number as user %2; numbers must be unique.</source>
        <translation>%1 has the same user number as user %2; numbers must be unique.</translation>
    </message>
    <message>
        <source>PLC network area 0x%1 is unknown; allowed are 0x08 (O), 0x09 (P), 0x0A (M) and 0x0B (X).</source>
        <translation>PLC network area 0x%1 is unknown; allowed are 0x08 (O), 0x09 (P), 0x0A (M) and 0x0B (X).</translation>
    </message>
    <message>
        <source>PLC network number %1 is outside 0..%2.</source>
        <translation>PLC network number %1 is outside 0..%2.</translation>
    </message>
    <message>
        <source>%1 is not an integer</source>
        <translation>%1 is not an integer</translation>
    </message>
    <message>
        <source>%1 is not a string</source>
        <translation>%1 is not a string</translation>
    </message>
    <message>
        <source>%1 is not true or false</source>
        <translation>%1 is not true or false</translation>
    </message>
    <message>
        <source>a JSON object is expected</source>
        <translation>a JSON object is expected</translation>
    </message>
    <message>
        <source>a JSON array is expected</source>
        <translation>a JSON array is expected</translation>
    </message>
    <message>
        <source>This is not a CamBench %1: it is not valid JSON (line %2: %3). The file may be truncated or damaged.</source>
        <translation>This is not a CamBench %1: it is not valid JSON (line %2: %3). The file may be truncated or damaged.</translation>
    </message>
    <message>
        <source>This is not a CamBench %1: the JSON holds no object.</source>
        <translation>This is not a CamBench %1: the JSON holds no object.</translation>
    </message>
    <message>
        <source>This is not a CamBench %1: its &quot;format&quot; is %2, expected &quot;%3&quot;.</source>
        <translation>This is not a CamBench %1: its &quot;format&quot; is %2, expected &quot;%3&quot;.</translation>
    </message>
    <message>
        <source>the format version</source>
        <translation>the format version</translation>
    </message>
    <message>
        <source>This %1 was written by a newer CamBench (format version %2); this CamBench reads version %3. Open it with a newer CamBench.</source>
        <translation>This %1 was written by a newer CamBench (format version %2); this CamBench reads version %3. Open it with a newer CamBench.</translation>
    </message>
    <message>
        <source>%1 %2 is not a multiple of 8</source>
        <translation>%1 %2 is not a multiple of 8</translation>
    </message>
    <message>
        <source>EPROM date</source>
        <translation>EPROM date</translation>
    </message>
    <message>
        <source>maximum position %1 is not above the minimum position %2</source>
        <translation>maximum position %1 is not above the minimum position %2</translation>
    </message>
    <message>
        <source>program number</source>
        <translation>program number</translation>
    </message>
    <message>
        <source>program name</source>
        <translation>program name</translation>
    </message>
    <message>
        <source>program %1 appears twice</source>
        <translation>program %1 appears twice</translation>
    </message>
    <message>
        <source>output %1 appears twice</source>
        <translation>output %1 appears twice</translation>
    </message>
    <message>
        <source>a cam is a pair [switch-on point, switch-off point], this has %1 values</source>
        <translation>a cam is a pair [switch-on point, switch-off point], this has %1 values</translation>
    </message>
    <message>
        <source>switch-on point</source>
        <translation>switch-on point</translation>
    </message>
    <message>
        <source>switch-off point</source>
        <translation>switch-off point</translation>
    </message>
    <message>
        <source>dead time</source>
        <translation>dead time</translation>
    </message>
    <message>
        <source>%1 %2 appears twice</source>
        <translation>%1 %2 appears twice</translation>
    </message>
    <message>
        <source>user name</source>
        <translation>user name</translation>
    </message>
    <message>
        <source>user number</source>
        <translation>user number</translation>
    </message>
    <message>
        <source>&quot;all outputs&quot;</source>
        <translation>&quot;all outputs&quot;</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no ISO 8601 time</source>
        <translation>&quot;%1&quot; is no ISO 8601 time</translation>
    </message>
    <message>
        <source>Program %1 appears twice.</source>
        <translation>Program %1 appears twice.</translation>
    </message>
    <message>
        <source>Program %1 is named &quot;%2&quot;, but the list of program names says &quot;%3&quot;.</source>
        <translation>Program %1 is named &quot;%2&quot;, but the list of program names says &quot;%3&quot;.</translation>
    </message>
    <message>
        <source>PLC network %1 of area 0x%2 appears twice.</source>
        <translation>PLC network %1 of area 0x%2 appears twice.</translation>
    </message>
    <message>
        <source>Block %1 (entry %2 of the list)</source>
        <translation>Block %1 (entry %2 of the list)</translation>
    </message>
    <message>
        <source>block number</source>
        <translation>block number</translation>
    </message>
    <message>
        <source>block data</source>
        <translation>block data</translation>
    </message>
    <message>
        <source>block data is not an even number of hex digits</source>
        <translation>block data is not an even number of hex digits</translation>
    </message>
    <message>
        <source>The image holds no blocks.</source>
        <translation>The image holds no blocks.</translation>
    </message>
    <message>
        <source>The image does not start with block 0000 (the basic parameters) but with block %1.</source>
        <translation>The image does not start with block 0000 (the basic parameters) but with block %1.</translation>
    </message>
    <message>
        <source>Block 0000 has %1 bytes; the basic-parameter block has %2.</source>
        <translation>Block 0000 has %1 bytes; the basic-parameter block has %2.</translation>
    </message>
    <message>
        <source>%1 does not follow block %2: block numbers must ascend.</source>
        <translation>%1 does not follow block %2: block numbers must ascend.</translation>
    </message>
    <message>
        <source>%1: FFFF marks the end of the EEPROM and is no block.</source>
        <translation>%1: FFFF marks the end of the EEPROM and is no block.</translation>
    </message>
    <message>
        <source>%1: its first byte 0x%2 gives no length (upper 4 bits are 0).</source>
        <translation>%1: its first byte 0x%2 gives no length (upper 4 bits are 0).</translation>
    </message>
    <message>
        <source>%1 has %2 bytes, but its first byte 0x%3 says %4.</source>
        <translation>%1 has %2 bytes, but its first byte 0x%3 says %4.</translation>
    </message>
    <message>
        <source>%1: image %2, device %3.</source>
        <translation>%1: image %2, device %3.</translation>
    </message>
    <message>
        <source>The file was changed or damaged: its SHA-256 checksum does not match its content. Do not restore it; take a new backup.</source>
        <translation>The file was changed or damaged: its SHA-256 checksum does not match its content. Do not restore it; take a new backup.</translation>
    </message>
    <message>
        <source>time taken</source>
        <translation>time taken</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;%1&quot; is not an ISO 8601 date and time</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>%1 was not saved: %2</translation>
    </message>
    <message>
        <source>Line %1: %2. Nothing was imported.</source>
        <translation>Line %1: %2. Nothing was imported.</translation>
    </message>
    <message>
        <source>a quoted field has no closing quote</source>
        <translation>a quoted field has no closing quote</translation>
    </message>
    <message>
        <source>there is text after a closing quote</source>
        <translation>there is text after a closing quote</translation>
    </message>
    <message>
        <source>The file is not UTF-8 text. Nothing was imported.</source>
        <translation>The file is not UTF-8 text. Nothing was imported.</translation>
    </message>
    <message>
        <source>the header must be &quot;%1&quot;, found &quot;%2&quot;</source>
        <translation>the header must be &quot;%1&quot;, found &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 fields, expected %2 (%3)</source>
        <translation>%1 fields, expected %2 (%3)</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not a whole number</source>
        <translation>%1 &quot;%2&quot; is not a whole number</translation>
    </message>
    <message>
        <source>output %1 has a cam %2 already (line %3)</source>
        <translation>output %1 has a cam %2 already (line %3)</translation>
    </message>
    <message>
        <source>cam %1 of output %2, but cam %3 is missing; number the cams of an output 1, 2, 3, ...</source>
        <translation>cam %1 of output %2, but cam %3 is missing; number the cams of an output 1, 2, 3, ...</translation>
    </message>
    <message>
        <source>output %1 has a dead time already (line %2)</source>
        <translation>output %1 has a dead time already (line %2)</translation>
    </message>
    <message>
        <source>kind &quot;%1&quot; is neither &quot;output&quot; nor &quot;program&quot;</source>
        <translation>kind &quot;%1&quot; is neither &quot;output&quot; nor &quot;program&quot;</translation>
    </message>
    <message>
        <source>%1 %2 has a name already (line %3)</source>
        <translation>%1 %2 has a name already (line %3)</translation>
    </message>
    <message>
        <source>there is no such setting</source>
        <translation>there is no such setting</translation>
    </message>
    <message>
        <source>the value is not a text</source>
        <translation>the value is not a text</translation>
    </message>
    <message>
        <source>the value</source>
        <translation>the value</translation>
    </message>
    <message>
        <source>the area &quot;%1&quot; is none of O, P, M, X</source>
        <translation>the area &quot;%1&quot; is none of O, P, M, X</translation>
    </message>
    <message>
        <source>&quot;area&quot; is missing</source>
        <translation>&quot;area&quot; is missing</translation>
    </message>
    <message>
        <source>network number</source>
        <translation>network number</translation>
    </message>
    <message>
        <source>reset field</source>
        <translation>reset field</translation>
    </message>
    <message>
        <source>%1 symbols, expected %2 (%3 paths of %4)</source>
        <translation>%1 symbols, expected %2 (%3 paths of %4)</translation>
    </message>
    <message>
        <source>network %1%2 appears twice</source>
        <translation>network %1%2 appears twice</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no ISO time</source>
        <translation>&quot;%1&quot; is no ISO time</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is neither &quot;saved&quot; nor &quot;failed&quot;</source>
        <translation>&quot;%1&quot; is neither &quot;saved&quot; nor &quot;failed&quot;</translation>
    </message>
    <message>
        <source>device %1 appears twice</source>
        <translation>device %1 appears twice</translation>
    </message>
    <message>
        <source> (0 = none)</source>
        <translation> (0 = none)</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>program %1</translation>
    </message>
    <message>
        <source>, output %1</source>
        <translation>, output %1</translation>
    </message>
    <message>
        <source>, cam %1</source>
        <translation>, cam %1</translation>
    </message>
    <message>
        <source>User %1 (%2)</source>
        <translation>User %1 (%2)</translation>
    </message>
    <message>
        <source>%1 %2 is outside %3..%4</source>
        <translation>%1 %2 is outside %3..%4</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 is empty.</translation>
    </message>
    <message>
        <source>area (O, P, M or X)</source>
        <translation>area (O, P, M or X)</translation>
    </message>
    <message>
        <source>PLC network %1%2</source>
        <translation type="unfinished">PLC network %1%2</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 has no dead-time compensation on this device (outputs 1..%2 have one).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: dead-time mode %2 is unknown (0 normal, 1 on/off, 2 path-time).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the dead time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the switch-on dead time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the switching time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the switch-off dead time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1 does not exist (1..%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1 has %2 base points; at most %3 fit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1, base point %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: position %2 is outside %3..%4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: position %2 does not come after the previous point&apos;s %3; order the points by position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: value %2 is outside %3..%4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming program %1 does not exist (programs 0..%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming program select mode %1 is unknown (0 slow, 1 direct, 2 at the actual value).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming program switch value %1 is outside %2..%3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot make it readable by its owner only (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>symbol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dead-time mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown mode &quot;%1&quot;; use normal, on/off or path-time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switch-on dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switch-off dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the dead time %2 and the dead time of its dead-time mode %3 (0.1 ms) differ, but the device holds one value for both.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>analogue output %1 has base points and a row without any; use &quot;%1,,&quot; only for an output without points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>analogue output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a base point is [position, value], two numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>analogue output %1 appears twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>select mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown select mode &quot;%1&quot;; use slow, direct or at-value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switch value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This %1 is for devices of the family &quot;%2&quot;, not &quot;%3&quot;: nothing was loaded. Open it where a device of that family is connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>minimum pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an even number of hexadecimal digits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a pair [number, value]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>variable number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value (%1 bits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V%1 a second time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 bytes from 0x%2 do not fit memory 0x0000–0xFFFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overlaps the range before it or is out of order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>controller variant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is none of mc100v1, mc100v2, mc200v1, mc200v2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flag page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 bytes, not the page&apos;s %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sha256: the checksum is missing.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 a second time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is none of auto, mc100v1, mc100v2, mc200v1, mc200v2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a variable such as V12</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a flag, input or output such as M2327</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a Compax3 object; write index.subindex, e.g. 680.5 (also o680.5, O 680,5, $ for hexadecimal; index up to 65535, subindex up to 255)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at least %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a text for the drive cannot hold &quot; or a line break</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot;: write the number with a decimal point (%2); the drive takes a comma for a syntax error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number (decimal, or $ and hexadecimal digits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is outside the object&apos;s range (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no value given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>access</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not integer, real or text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not ro, rw, wo or cmd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>min is above max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>object %1 a second time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>built in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2) is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>info string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an object of name, group and help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a control word: a file never starts or stops the axis (use the Motion page or c3 enable/jog/move/stop)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a function, not a value: a file never triggers it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>language of the Compax3 refusals: en</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>object %1 both with a value and absent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1, output %2</source>
        <translation type="unfinished">program %1, output %2</translation>
    </message>
    <message>
        <source>%1 flags, not the page&apos;s %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not [&quot;%1&quot;, 0 or 1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not [&quot;object&quot;, &quot;value&quot;, &quot;name&quot;]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not an object of names and texts ({&quot;serial&quot;: &quot;...&quot;}).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; must be a text, as CamBench wrote it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>which device this is cannot be told: no identity was recorded for it; found %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished">none</translation>
    </message>
    <message>
        <source>another device answers: expected %1, found %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 records no identity of the device it was taken from (a backup older than that record), so CamBench cannot tell whether the device answering (%2) is that device. Nothing was written. If it is, or if it replaces that device, confirm it (on the command line: --replacement).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 was taken from another device: %2 (the backup&apos;s device: %3; the device answering: %4). Nothing was written. Only if this device replaces that one, confirm it (on the command line: --replacement).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The git program could not be started (%1); the machine archive is a git repository: install git (Debian: apt install git).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 in %2 did not finish within %3 s (a lock held by another git?); nothing more was done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 in %2 failed (exit %3): %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is no machine archive: there is no such folder (`machine backup M.json --archive %1` makes one).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is no machine archive: it is not the top folder of a git repository (`machine backup M.json --archive DIR` makes one).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot make the archive folder %1; check the path and its rights.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds files but is no git repository: it is not made an archive (name an empty or new folder).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 names no version of %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds no version yet (`machine backup M.json --archive %1 -m WHY` stores the first).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 names no version of %2 (`machine history %2` lists them: a commit id, a prefix of one or a tag).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No version of %1 is released (`machine release %1 VERSION` marks the one that should be on the machine).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot make the folder for %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read %1: %2; no version was stored.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::plcsymbol</name>
    <message>
        <source>&quot;%1&quot; is not taken: CamBench knows the operands O, P, M and X only (P are the cam controller&apos;s inputs, e.g. P5). Enter one of them with a number, or the symbol word as 4 hex digits.</source>
        <translation>&quot;%1&quot; is not taken: CamBench knows the operands O, P, M and X only (P are the cam controller&apos;s inputs, e.g. P5). Enter one of them with a number, or the symbol word as 4 hex digits.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not taken: the number must be 1 … 256.</source>
        <translation>&quot;%1&quot; is not taken: the number must be 1 … 256.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not taken: enter an operand such as M11 or P5, 4 hex digits (0A0A), or nothing to clear the symbol.</source>
        <translation>&quot;%1&quot; is not taken: enter an operand such as M11 or P5, 4 hex digits (0A0A), or nothing to clear the symbol.</translation>
    </message>
</context>
<context>
    <name>cambench::usecases</name>
    <message>
        <source>, the device keeps %1</source>
        <translation>, the device keeps %1</translation>
    </message>
    <message>
        <source>, the device NOW HOLDS %1</source>
        <translation>, the device NOW HOLDS %1</translation>
    </message>
    <message>
        <source>, what the device holds now could not be read</source>
        <translation>, what the device holds now could not be read</translation>
    </message>
    <message>
        <source>written</source>
        <translation>written</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unchanged</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <source>changed though the write failed</source>
        <translation>changed though the write failed</translation>
    </message>
    <message>
        <source>failed, state unknown</source>
        <translation>failed, state unknown</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>not sent</translation>
    </message>
    <message>
        <source>%1 written</source>
        <translation>%1 written</translation>
    </message>
    <message>
        <source>%1 unchanged</source>
        <translation>%1 unchanged</translation>
    </message>
    <message>
        <source>%1 failed (the device keeps its old values)</source>
        <translation>%1 failed (the device keeps its old values)</translation>
    </message>
    <message>
        <source>%1 CHANGED THOUGH THE WRITE FAILED</source>
        <translation>%1 CHANGED THOUGH THE WRITE FAILED</translation>
    </message>
    <message>
        <source>%1 failed with the device&apos;s state unknown</source>
        <translation>%1 failed with the device&apos;s state unknown</translation>
    </message>
    <message>
        <source>%1 not sent</source>
        <translation>%1 not sent</translation>
    </message>
    <message>
        <source>%1 items: %2</source>
        <translation>%1 items: %2</translation>
    </message>
    <message>
        <source>no cams</source>
        <translation>no cams</translation>
    </message>
    <message>
        <source>no name</source>
        <translation>no name</translation>
    </message>
    <message>
        <source>no values</source>
        <translation>no values</translation>
    </message>
    <message>
        <source>no such user</source>
        <translation>no such user</translation>
    </message>
    <message>
        <source>user %1 with rights 0x%2 and %3</source>
        <translation>user %1 with rights 0x%2 and %3</translation>
    </message>
    <message>
        <source>all outputs</source>
        <translation>all outputs</translation>
    </message>
    <message>
        <source>%1 outputs</source>
        <translation>%1 outputs</translation>
    </message>
    <message>
        <source>value %1, reset 0x%2, %3 symbols set</source>
        <translation>value %1, reset 0x%2, %3 symbols set</translation>
    </message>
    <message>
        <source>program %1, output %2</source>
        <translation>program %1, output %2</translation>
    </message>
    <message>
        <source>dead time of output %1</source>
        <translation>dead time of output %1</translation>
    </message>
    <message>
        <source>name of output %1</source>
        <translation>name of output %1</translation>
    </message>
    <message>
        <source>name of program %1</source>
        <translation>name of program %1</translation>
    </message>
    <message>
        <source>settings %1 (%2)</source>
        <translation>settings %1 (%2)</translation>
    </message>
    <message>
        <source>user %1</source>
        <translation>user %1</translation>
    </message>
    <message>
        <source>PLC network %1%2</source>
        <translation>PLC network %1%2</translation>
    </message>
    <message>
        <source>Setting %1: there is no such setting.</source>
        <translation>Setting %1: there is no such setting.</translation>
    </message>
    <message>
        <source>Setting %1 is read-only: the device decides it (wanted %2%3).</source>
        <translation>Setting %1 is read-only: the device decides it (wanted %2%3).</translation>
    </message>
    <message>
        <source>, the device has %1</source>
        <translation>, the device has %1</translation>
    </message>
    <message>
        <source>Name of program %1: the device has programs 0..%2.</source>
        <translation>Name of program %1: the device has programs 0..%2.</translation>
    </message>
    <message>
        <source>Name of program %1: %2.</source>
        <translation>Name of program %1: %2.</translation>
    </message>
    <message>
        <source>Program %1: the device has programs 0..%2.</source>
        <translation>Program %1: the device has programs 0..%2.</translation>
    </message>
    <message>
        <source>%1: the plan holds this track twice.</source>
        <translation>%1: the plan holds this track twice.</translation>
    </message>
    <message>
        <source>%1: the device has outputs 1..%2.</source>
        <translation>%1: the device has outputs 1..%2.</translation>
    </message>
    <message>
        <source>Dead time of output %1: the device compensates outputs 1..%2 only.</source>
        <translation>Dead time of output %1: the device compensates outputs 1..%2 only.</translation>
    </message>
    <message>
        <source>Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).</source>
        <translation>Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).</translation>
    </message>
    <message>
        <source>Name of output %1: the device has outputs 1..%2.</source>
        <translation>Name of output %1: the device has outputs 1..%2.</translation>
    </message>
    <message>
        <source>Name of output %1: %2.</source>
        <translation>Name of output %1: %2.</translation>
    </message>
    <message>
        <source>%1: the device has no user with the number given for it; read the users again.</source>
        <translation>%1: the device has no user with the number given for it; read the users again.</translation>
    </message>
    <message>
        <source>%1 has no number and the device has no user of that name whose number it could keep; enter a number.</source>
        <translation>%1 has no number and the device has no user of that name whose number it could keep; enter a number.</translation>
    </message>
    <message>
        <source>%1 would have the same user number as %2; numbers must be unique.</source>
        <translation>%1 would have the same user number as %2; numbers must be unique.</translation>
    </message>
    <message>
        <source>%1: the device has %2 networks in area %3 (%3%4); change the PLC counts in the settings first.</source>
        <translation>%1: the device has %2 networks in area %3 (%3%4); change the PLC counts in the settings first.</translation>
    </message>
    <message>
        <source>outputs %1 do not exist on the device (it has 1..%2)</source>
        <translation>outputs %1 do not exist on the device (it has 1..%2)</translation>
    </message>
    <message>
        <source>programs %1 do not exist on the device (it has 0..%2)</source>
        <translation>programs %1 do not exist on the device (it has 0..%2)</translation>
    </message>
    <message>
        <source>%1 cam points lie outside the device&apos;s range %2..%3</source>
        <translation>%1 cam points lie outside the device&apos;s range %2..%3</translation>
    </message>
    <message>
        <source>the plan holds invalid values</source>
        <translation>the plan holds invalid values</translation>
    </message>
    <message>
        <source>The write was refused before anything was sent: %1 (%2):</source>
        <translation>The write was refused before anything was sent: %1 (%2):</translation>
    </message>
    <message>
        <source>
  and %1 more</source>
        <translation>
  and %1 more</translation>
    </message>
    <message>
        <source>reading it before the write</source>
        <translation>reading it before the write</translation>
    </message>
    <message>
        <source> Reading it back failed too: %1</source>
        <translation> Reading it back failed too: %1</translation>
    </message>
    <message>
        <source>read back after the error &quot;%1&quot;</source>
        <translation>read back after the error &quot;%1&quot;</translation>
    </message>
    <message>
        <source>not sent: the connection failed at %1; nothing after it was sent</source>
        <translation>not sent: the connection failed at %1; nothing after it was sent</translation>
    </message>
    <message>
        <source>the device held %1, not %2 as last read</source>
        <translation>the device held %1, not %2 as last read</translation>
    </message>
    <message>
        <source>reading the settings</source>
        <translation>reading the settings</translation>
    </message>
    <message>
        <source>reading the users</source>
        <translation>reading the users</translation>
    </message>
    <message>
        <source>read everything</source>
        <translation>read everything</translation>
    </message>
    <message>
        <source>reading program %1</source>
        <translation>reading program %1</translation>
    </message>
    <message>
        <source>reading dead times</source>
        <translation>reading dead times</translation>
    </message>
    <message>
        <source>Output names</source>
        <translation>Output names</translation>
    </message>
    <message>
        <source>reading output names</source>
        <translation>reading output names</translation>
    </message>
    <message>
        <source>Output names: %1</source>
        <translation>Output names: %1</translation>
    </message>
    <message>
        <source>reading users</source>
        <translation>reading users</translation>
    </message>
    <message>
        <source>PLC networks</source>
        <translation>PLC networks</translation>
    </message>
    <message>
        <source>reading PLC networks</source>
        <translation>reading PLC networks</translation>
    </message>
    <message>
        <source>reading the EEPROM</source>
        <translation>reading the EEPROM</translation>
    </message>
    <message>
        <source>%1 The device was not changed.</source>
        <translation>%1 The device was not changed.</translation>
    </message>
    <message>
        <source>step 1 of 2: safety backup</source>
        <translation>step 1 of 2: safety backup</translation>
    </message>
    <message>
        <source>Cannot take the safety backup before the restore: %1 The device was not changed.</source>
        <translation>Cannot take the safety backup before the restore: %1 The device was not changed.</translation>
    </message>
    <message>
        <source>Cancelled before the restore started. The device was not changed.</source>
        <translation>Cancelled before the restore started. The device was not changed.</translation>
    </message>
    <message>
        <source>step 2 of 2: restore</source>
        <translation>step 2 of 2: restore</translation>
    </message>
    <message>
        <source> No safety backup was taken.</source>
        <translation> No safety backup was taken.</translation>
    </message>
    <message>
        <source> The device&apos;s previous content is in the safety backup %1.</source>
        <translation> The device&apos;s previous content is in the safety backup %1.</translation>
    </message>
    <message>
        <source>the device equals %1 (%2 blocks)</source>
        <translation>the device equals %1 (%2 blocks)</translation>
    </message>
    <message>
        <source>the device differs from %1: device %2 blocks, image %3 blocks</source>
        <translation>the device differs from %1: device %2 blocks, image %3 blocks</translation>
    </message>
    <message>
        <source>; first differing blocks: %1</source>
        <translation>; first differing blocks: %1</translation>
    </message>
    <message>
        <source>%1 was written but does not read back as the image taken; check the disk</source>
        <translation>%1 was written but does not read back as the image taken; check the disk</translation>
    </message>
    <message>
        <source>scanning the line</source>
        <translation>scanning the line</translation>
    </message>
    <message>
        <source>no device answered on the line (numbers 0..63); check the cable, the baud rate and the protocol</source>
        <translation>no device answered on the line (numbers 0..63); check the cable, the baud rate and the protocol</translation>
    </message>
    <message>
        <source>cannot create the folder %1; choose another one</source>
        <translation>cannot create the folder %1; choose another one</translation>
    </message>
    <message>
        <source>not backed up: the run was cancelled</source>
        <translation>not backed up: the run was cancelled</translation>
    </message>
    <message>
        <source>saved by an earlier run</source>
        <translation>saved by an earlier run</translation>
    </message>
    <message>
        <source>line backed up</source>
        <translation>line backed up</translation>
    </message>
    <message>
        <source>not verified: its backup failed (%1)</source>
        <translation>not verified: its backup failed (%1)</translation>
    </message>
    <message>
        <source>%1 is missing or was changed since the backup (SHA-256 differs from the manifest)</source>
        <translation>%1 is missing or was changed since the backup (SHA-256 differs from the manifest)</translation>
    </message>
    <message>
        <source>line verified</source>
        <translation>line verified</translation>
    </message>
    <message>
        <source>Setting %1: %2.</source>
        <translation>Setting %1: %2.</translation>
    </message>
    <message>
        <source>to delete</source>
        <translation>to delete</translation>
    </message>
    <message>
        <source>1 problem</source>
        <translation>1 problem</translation>
    </message>
    <message>
        <source>%1 problems</source>
        <translation>%1 problems</translation>
    </message>
    <message>
        <source> (before: %1)</source>
        <translation> (before: %1)</translation>
    </message>
    <message>
        <source>device %1</source>
        <translation>device %1</translation>
    </message>
    <message>
        <source>device %1: </source>
        <translation>device %1: </translation>
    </message>
    <message>
        <source>Users</source>
        <translation type="unfinished">Users</translation>
    </message>
    <message>
        <source>restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 item: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acknowledged; reading it back failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device acknowledged the write, but reads back another value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error reset (0x02)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>device status now: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the device status failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; the cause is still there: check the encoder and the outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>active program (0x03)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1</source>
        <translation type="unfinished">program %1</translation>
    </message>
    <message>
        <source>program %1, output %2 (0x05)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dead time of output %1 (0x07)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>normal, %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on/off, switch-on %1, switch-off %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>path-time, switch-on %1, switching time %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dead-time mode of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1: the dead time %2 and the dead time of its dead-time mode %3 differ, but the device holds one value for both.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading dead-time modes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no base points</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n base point(s): %1</source>
        <translation>
            <numerusform>%n base point: %1</numerusform>
            <numerusform>%n base points: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>program %1, changed slowly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1, changed directly (within one cycle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1, changed at the actual value %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1, select mode %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>locked (changes stay in RAM only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unlocked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>analogue output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output %1 is to be written twice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the cams changed the programming program; setting it back to %1 failed (%2): check it on the Programming program page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether the device&apos;s EEPROM is locked could not be read (%1): if it is, what was written is held in RAM only and is lost when the device is switched off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device&apos;s EEPROM is locked: what was written is held in RAM only and is lost when the device is switched off. Unlock the EEPROM to keep it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the programming program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the programs selected program %1 as the programming program; setting it back to program %2 failed: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading analogue output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the EEPROM lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>memory %1–%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file was taken from an %1, the controller is an %2 (variables of other widths, flags elsewhere): nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file&apos;s flags are on page %1, the %2 keeps them on page %3: nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file holds memory ranges, which the %1 cannot write (an MC200 V2 can): nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>written, as read back after: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 has no memory telegrams (an MC200 has): leave out --mem</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read back %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the other %1 flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the bytes read back differ from those written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 read %2 times, no two answers in a row agreed: the line damages answers (check the cable, its shield and the baud rate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: file %2, drive: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: file %2, drive %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comparing objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file&apos;s value of %1 cannot be written: %2. Nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not in the file: nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drive took it but reads back %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not stored, because not every object was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 was not sent: the check only reads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 was not loaded: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no family&apos;s check takes %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no check for %1 devices yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a table of %2 devices; the device connected is a %3 device: leave the option out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this device has no analogue outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this device has analogue outputs 1..%1 only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1; its base points are not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings the device does not know, not read: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue cams: this device has no analogue outputs, so it has no analogue cams.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no check for the protocol %1 yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it asks with a text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device does not know it (:Z): %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it answered ERR %1 when asked with 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device stopped answering</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is answered as manual %2 reads%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (provisional format)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a request under a new block number is answered, and so is a repeat of that number (with the last reply, not executed again)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer under block numbers %1 (of %2, %2, %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every user in the bus&apos;s table gets the token within a second (P11: each answers within T = 10 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a Cam-BUS line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no token heard in %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 tokens in %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1; users %2 did not get the token</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>area %1 word %2 can be read: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (provisional: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>area 203 word 38 holds the number of analogue outputs (0..14), and only their areas 241.. exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it says %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this variant of the protocol cannot address the word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the variant shows in RDVAR&apos;s width, then in SYSDATA or RDBLOCK being answered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RDVAR answers 24 bits on an MC100 and 32 bits on an MC200, two&apos;s complement (P3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flag Mn read by itself and bit n-1 of the flags&apos; external RAM page agree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read by themselves, %1 differ from the page (or changed between the reads)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inputs E1..E8 and outputs A1..A8 are read at the addresses of tables 47/48 and answered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RDTABLE answers for each logical axis 1..8 the controller has (logical n is physical n-1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this variant has no axis telegrams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axes %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the axis parameter table in use (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller has no axes (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 of axis %2 is RDSTAT parameter %3 (0x%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 of axis %2 (the table names no parameter for it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not in the table, not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>answered %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: file: not on the drive it was read from, drive %2 (left as it is)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not on this drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is from a drive of type %1 (&quot;%2&quot;), the connected drive is of type %3 (&quot;%4&quot;): nothing was written. Restore it with --force (GUI: &quot;Write to another drive type&quot;) only if you know the objects mean the same on both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>store set %1 in the drive&apos;s flash (1904.%1 = $32)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not on this drive (%1): not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>store the sets in the drive&apos;s flash (1904.n = $32)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the info string (_?) starts with &quot;Compax3&quot; and its second word is the drive type (C7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>O1.4 and O1,4 name the same object (the manual writes &apos;,&apos;, the public client &apos;.&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>O1,4 answered %1, O1.4 answered %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a whole number asked for in hex ($) is answered with its $ (C8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an object the drive lacks is refused with !%1 (C5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a text asked for in hex is refused with !0006 (C5, C8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>object %1 (%2) exists and is %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1 does not exist: the device reports no programs; read its identity again or check the connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program %1 does not exist on the device (it has programs 0 to %2): choose one of those</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 family has no backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not reached: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>incomplete: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a device of the %2 family in one folder and of the %3 family in the other: not compared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machine name %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: family %2 → %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 → %3</source>
        <translation type="unfinished">%1: %2 → %3</translation>
    </message>
    <message>
        <source>%1: volatile items %2 → %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not saved in %1%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another device: %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is no machine backup folder: %2 (made by `machine backup`)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: added (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: taken out of the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>first version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>first version: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No temporary folder to take version %1 out of %2 into: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 not saved: no version was stored (a version without a device would read as the device taken out of the machine).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The backup could not be compared with the latest version, no version was stored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Communication settings left out: %1 (the device keeps %2). They decide how the device is reached and are written only when asked for by name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether the communication settings changed is not known: if the next connection fails, try the settings that were to be written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Communication settings written: the next connection to this device needs %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The image holds the communication settings the device had when it was taken, %1 (it uses %2 now). A restore puts them back with everything else: the next connection to the device needs %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM: blocks %1 differ%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (a backup of the older format: its content is not decoded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (the decoded content is equal: what differs is not in it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device reports %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the flag page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 bytes differ, from %3: %4 → %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>variant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The parameter set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not on the drive it was read from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file&apos;s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not on the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machine file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 EEPROM blocks (%2 bytes), decoded: %3 programs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a safety copy of what the device holds now is saved first%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>then the whole EEPROM is erased and written again: %1 blocks, and the device starts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (a safety copy was saved to %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM, %1 blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>erased or partly written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 variables and %2 flags of the %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only the differing variables, flags and memory are written, each read back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 objects of %2 (serial number %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; %1 objects are not on this drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not saved: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 objects are not on this drive, nor on the file&apos;s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not compared: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only the differing objects are written, each read back; control words and functions never from a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not saved in the version%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its backup now %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read from the device now</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
