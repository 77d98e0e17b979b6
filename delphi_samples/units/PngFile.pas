{ PngFile.pas -- writes an RGBA8 image as an RGB PNG file (the window
  shows no alpha) (PNG 1.2 spec: IHDR,
  one IDAT holding a zlib stream of stored (uncompressed) deflate blocks,
  IEND; CRC-32 per chunk, Adler-32 over the stream).  Uncompressed keeps the
  writer short and obviously right; the runner recompresses goldens with
  imgcmp --to-png.  Rows come bottom-up, as glReadPixels and
  softglGetDCImage give them, and are written top-down. }
unit PngFile;

{$mode delphi}

interface

function WritePNG(const FileName: string; W, H: Integer; BottomUpRGBA: PByte): Boolean;

implementation

uses SysUtils, Classes;

var
  CrcTable: array[0..255] of LongWord;

procedure MakeCrcTable;
var n, k: Integer; c: LongWord;
begin
  for n := 0 to 255 do
  begin
    c := n;
    for k := 0 to 7 do
      if (c and 1) <> 0 then c := $EDB88320 xor (c shr 1) else c := c shr 1;
    CrcTable[n] := c;
  end;
end;

function UpdateCrc(crc: LongWord; p: PByte; len: SizeInt): LongWord;
var i: SizeInt;
begin
  Result := crc;
  for i := 0 to len - 1 do
    Result := CrcTable[(Result xor p[i]) and $FF] xor (Result shr 8);
end;

procedure PutBE(s: TStream; v: LongWord);
var b: array[0..3] of Byte;
begin
  b[0] := v shr 24; b[1] := (v shr 16) and $FF; b[2] := (v shr 8) and $FF; b[3] := v and $FF;
  s.WriteBuffer(b, 4);
end;

procedure PutChunk(s: TStream; const Kind: AnsiString; Data: PByte; Len: SizeInt);
var crc: LongWord;
begin
  PutBE(s, Len);
  s.WriteBuffer(Kind[1], 4);
  if Len > 0 then s.WriteBuffer(Data^, Len);
  crc := UpdateCrc($FFFFFFFF, PByte(@Kind[1]), 4);
  if Len > 0 then crc := UpdateCrc(crc, Data, Len);
  PutBE(s, crc xor $FFFFFFFF);
end;

function WritePNG(const FileName: string; W, H: Integer; BottomUpRGBA: PByte): Boolean;
const
  Sig: array[0..7] of Byte = (137, 80, 78, 71, 13, 10, 26, 10);
var
  raw, z: array of Byte;
  rowLen, rawLen, pos, zpos, n, x, y: SizeInt;
  a, b: LongWord;
  ihdr: array[0..12] of Byte;
  f: TFileStream;
  i: SizeInt;
begin
  Result := False;
  if (W <= 0) or (H <= 0) or (BottomUpRGBA = nil) then Exit;
  rowLen := W * 3 + 1;                 { filter byte 0 (None) + RGB pixels }
  rawLen := rowLen * H;
  SetLength(raw, rawLen);
  for y := 0 to H - 1 do
  begin
    raw[y * rowLen] := 0;
    for x := 0 to W - 1 do
      Move(BottomUpRGBA[((H - 1 - y) * W + x) * 4], raw[y * rowLen + 1 + x * 3], 3);
  end;
  { zlib: CMF/FLG, stored blocks of at most 65535 bytes, Adler-32 }
  SetLength(z, 2 + rawLen + 5 * (rawLen div 65535 + 1) + 4);
  z[0] := $78; z[1] := $01;
  zpos := 2; pos := 0;
  repeat
    n := rawLen - pos;
    if n > 65535 then n := 65535;
    if pos + n = rawLen then z[zpos] := 1 else z[zpos] := 0;
    z[zpos + 1] := n and $FF; z[zpos + 2] := n shr 8;
    z[zpos + 3] := (not n) and $FF; z[zpos + 4] := ((not n) shr 8) and $FF;
    Move(raw[pos], z[zpos + 5], n);
    Inc(zpos, 5 + n); Inc(pos, n);
  until pos >= rawLen;
  a := 1; b := 0;
  for i := 0 to rawLen - 1 do
  begin
    a := (a + raw[i]) mod 65521;
    b := (b + a) mod 65521;
  end;
  a := (b shl 16) or a;
  z[zpos] := a shr 24; z[zpos + 1] := (a shr 16) and $FF;
  z[zpos + 2] := (a shr 8) and $FF; z[zpos + 3] := a and $FF;
  Inc(zpos, 4);

  ihdr[0] := W shr 24; ihdr[1] := (W shr 16) and $FF; ihdr[2] := (W shr 8) and $FF; ihdr[3] := W and $FF;
  ihdr[4] := H shr 24; ihdr[5] := (H shr 16) and $FF; ihdr[6] := (H shr 8) and $FF; ihdr[7] := H and $FF;
  ihdr[8] := 8; ihdr[9] := 2; ihdr[10] := 0; ihdr[11] := 0; ihdr[12] := 0;
  try
    f := TFileStream.Create(FileName, fmCreate);
    try
      f.WriteBuffer(Sig, 8);
      PutChunk(f, 'IHDR', @ihdr[0], 13);
      PutChunk(f, 'IDAT', @z[0], zpos);
      PutChunk(f, 'IEND', nil, 0);
    finally
      f.Free;
    end;
    Result := True;
  except
    on E: Exception do WriteLn('WritePNG ', FileName, ': ', E.Message);
  end;
end;

initialization
  MakeCrcTable;
end.
